#include "output/field_output.h"
#include "output/field_writer.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <memory>
#include <type_traits>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    template <class Problem, int dim = Problem::dimension>
    class StressPostprocessor : public DataPostprocessor<dim>
    {
    public:
      explicit StressPostprocessor(const Problem &problem) : problem(problem) {}

      void evaluate_vector_field(const DataPostprocessorInputs::Vector<dim> &inputs,
                                 std::vector<Vector<double>> &computed) const override
      {
        const auto      cell     = inputs.template get_cell<dim>();
        const Material &material = problem.materials.at(cell->material_id());
        for (unsigned int k = 0; k < inputs.solution_gradients.size(); ++k)
          {
            Tensor<2, dim> grad;
            for (unsigned int d = 0; d < dim; ++d)
              grad[d] = inputs.solution_gradients[k][d];
            // Green-Lagrange strain (the small strain in a linear analysis: the quadratic term
            // is negligible there); Cauchy stress.
            const SymmetricTensor<2, dim> strain =
              symmetrize(grad) + (nonlinear ? 0.5 * symmetrize(transpose(grad) * grad) :
                                              SymmetricTensor<2, dim>());
            const double pressure = inputs.solution_values[k].size() > dim ?
                                      inputs.solution_values[k][dim] : 0.0;
            double       sigma_zz;
            const auto   sigma = problem.cauchy_stress(grad, material, pressure, sigma_zz);
            // Every component as its own scalar (deal.II 9.4 writes tensors to HDF5/XDMF as
            // dim-component vectors and drops the rest), then principal stresses and von Mises.
            unsigned int c = 0;
            for (const auto &[i, j] : components())
              computed[k][c++] = strain[i][j];
            for (const auto &[i, j] : components())
              computed[k][c++] = sigma[i][j];
            if (dim == 2)
              computed[k][c++] = sigma_zz;
            std::array<double, 3> principal{{sigma_zz, sigma_zz, sigma_zz}};
            const auto            in_plane = eigenvalues(sigma);
            for (unsigned int d = 0; d < dim; ++d)
              principal[d] = in_plane[d];
            std::sort(principal.begin(), principal.end(), std::greater<double>());
            for (const double p : principal)
              computed[k][c++] = p;
            computed[k][c] = problem.von_mises(sigma, sigma_zz);
          }
      }

      // xx, yy, (zz,) xy, (xz, yz): the independent components of a symmetric tensor.
      static std::vector<std::pair<unsigned int, unsigned int>> components()
      {
        if (dim == 2)
          return {{0, 0}, {1, 1}, {0, 1}};
        return {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      }

      std::vector<std::string> get_names() const override
      {
        const char              axis[] = "xyz";
        std::vector<std::string> names;
        for (const char *field : {"strain", "stress"})
          for (const auto &[i, j] : components())
            names.push_back(std::string(field) + "_" + axis[i] + axis[j]);
        if (dim == 2) // plane strain: lambda tr(eps); plane stress: 0
          names.push_back("stress_zz");
        for (const char *principal : {"stress_1", "stress_2", "stress_3"})
          names.push_back(principal);
        names.push_back("von_mises");
        return names;
      }

      std::vector<DataComponentInterpretation::DataComponentInterpretation>
      get_data_component_interpretation() const override
      {
        return std::vector<DataComponentInterpretation::DataComponentInterpretation>(
          get_names().size(), DataComponentInterpretation::component_is_scalar);
      }

      UpdateFlags get_needed_update_flags() const override
      {
        return update_values | update_gradients;
      }

    private:
      const Problem &problem;
      const bool     nonlinear = !std::is_same_v<Problem, LinearElasticProblem<dim>>;
    };

    // Contact pressure and gap as scalar fields (deal.II's DataOut takes a second DoFHandler on
    // the same mesh): their values at the contact nodes, 0 off the contact boundaries. A face's
    // values depend on its own nodes only, so on the contact boundaries they are the nodes'.
    template <int dim>
    struct ContactFields
    {
      std::unique_ptr<FE_Q<dim>>                        fe;
      std::unique_ptr<DoFHandler<dim>>                  dofs;
      LinearAlgebra::distributed::Vector<double>        pressure, gap;
    };

    template <int dim>
    void add_contact_fields(DataOut<dim> &, const LinearElasticProblem<dim> &, ContactFields<dim> &)
    {}

    template <int dim>
    void add_contact_fields(DataOut<dim> &data_out, const FiniteStrainProblem<dim> &problem, ContactFields<dim> &fields)
    {
      if (!problem.contact)
        return;
      auto residual = problem.reaction_forces();
      residual *= -1; // f_ext - f_int
      PETScWrappers::MPI::Vector pressure(problem.locally_owned_dofs, problem.communicator), gap(pressure);
      problem.contact->nodal_fields(problem.solution, residual, problem.load_factor, pressure, gap);
      pressure.compress(VectorOperation::insert);
      gap.compress(VectorOperation::insert);
      PETScWrappers::MPI::Vector pressure_ghosted(problem.locally_owned_dofs, problem.locally_relevant_dofs,
                                                  problem.communicator),
        gap_ghosted(pressure_ghosted);
      pressure_ghosted = pressure;
      gap_ghosted      = gap;

      fields.fe   = std::make_unique<FE_Q<dim>>(problem.fe->base_element(0).degree);
      fields.dofs = std::make_unique<DoFHandler<dim>>(problem.triangulation);
      fields.dofs->distribute_dofs(*fields.fe);
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(*fields.dofs, relevant);
      fields.pressure.reinit(fields.dofs->locally_owned_dofs(), relevant, problem.communicator);
      fields.gap.reinit(fields.dofs->locally_owned_dofs(), relevant, problem.communicator);
      const auto &fe = *problem.fe;
      std::vector<types::global_dof_index> vector_dofs(fe.n_dofs_per_cell()), scalar_dofs(fields.fe->n_dofs_per_cell());
      auto scalar_cell = fields.dofs->begin_active();
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        {
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(vector_dofs);
              scalar_cell->get_dof_indices(scalar_dofs);
              for (unsigned int i = 0; i < vector_dofs.size(); ++i)
                if (fe.system_to_base_index(i).first == std::make_pair(0u, 0u)) // the x displacement
                  {
                    const auto j = scalar_dofs[fe.system_to_base_index(i).second];
                    if (fields.pressure.locally_owned_elements().is_element(j))
                      {
                        fields.pressure[j] = pressure_ghosted(vector_dofs[i]);
                        fields.gap[j]      = gap_ghosted(vector_dofs[i]);
                      }
                  }
            }
          ++scalar_cell;
        }
      fields.pressure.update_ghost_values();
      fields.gap.update_ghost_values();
      data_out.add_data_vector(*fields.dofs, fields.pressure, "contact_pressure");
      data_out.add_data_vector(*fields.dofs, fields.gap, "contact_gap");
    }
  } // namespace

  template <class Problem>
  std::string write_field_files(DataOut<Problem::dimension> &data_out, const Problem &problem,
                                const std::string &directory)
  {
    Vector<float> material_id(problem.triangulation.n_active_cells());
    Vector<float> partition(problem.triangulation.n_active_cells());
    for (const auto &cell : problem.triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          material_id(cell->active_cell_index()) = cell->material_id();
          partition(cell->active_cell_index())   = cell->subdomain_id();
        }
    data_out.add_data_vector(material_id, "material_id");
    data_out.add_data_vector(partition, "partition");
    // Subdivided patches show the higher-order field; deal.II 9.4 supports them on hypercubes only.
    const bool hypercube = problem.triangulation.all_reference_cells_are_hyper_cube();
    data_out.build_patches(*problem.mapping, hypercube ? problem.parameters.element_degree : 1);

    DataOutBase::DataOutFilter filter(DataOutBase::DataOutFilterFlags(true, true));
    data_out.write_filtered_data(filter);
    const std::string h5      = "fields.h5";
    const std::string partial = directory + "/" + h5 + ".partial";
    data_out.write_hdf5_parallel(filter, partial, problem.communicator);
    std::vector<XDMFEntry> entries{
      data_out.create_xdmf_entry(filter, h5, 0., problem.communicator)};
    const std::string xdmf = directory + "/fields.xdmf";
    data_out.write_xdmf_file(entries, xdmf + ".partial", problem.communicator);
    MPI_Barrier(problem.communicator);
    if (Utilities::MPI::this_mpi_process(problem.communicator) == 0)
      {
        std::rename(partial.c_str(), (directory + "/" + h5).c_str());
        std::rename((xdmf + ".partial").c_str(), xdmf.c_str());
      }
    MPI_Barrier(problem.communicator);
    return xdmf;
  }

  template <class Problem>
  std::string write_fields(const Problem &problem, const std::string &directory)
  {
    constexpr int      dim = Problem::dimension;
    ContactFields<dim> contact; // before data_out: it must outlive the patches
    DataOut<dim>       data_out;
    data_out.attach_dof_handler(problem.dof_handler);
    std::vector<std::string> names(dim, "displacement");
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    if (problem.fe->n_components() > dim)
      {
        names.emplace_back("pressure");
        interpretation.push_back(DataComponentInterpretation::component_is_scalar);
      }
    data_out.add_data_vector(problem.solution, names, DataOut<dim>::type_dof_data, interpretation);
    StressPostprocessor<Problem> stress(problem);
    data_out.add_data_vector(problem.solution, stress);
    add_contact_fields(data_out, problem, contact);

    return write_field_files(data_out, problem, directory);
  }

  template std::string write_field_files(DataOut<2> &, const LinearElasticProblem<2> &, const std::string &);
  template std::string write_field_files(DataOut<3> &, const LinearElasticProblem<3> &, const std::string &);
  template std::string write_field_files(DataOut<2> &, const Discretization<2> &, const std::string &);
  template std::string write_field_files(DataOut<3> &, const Discretization<3> &, const std::string &);
  template std::string write_fields(const LinearElasticProblem<2> &, const std::string &);
  template std::string write_fields(const LinearElasticProblem<3> &, const std::string &);
  template std::string write_fields(const FiniteStrainProblem<2> &, const std::string &);
  template std::string write_fields(const FiniteStrainProblem<3> &, const std::string &);
} // namespace compliant
