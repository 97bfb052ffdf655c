#include "analyses/modal_fields.h"

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // Largest displacement magnitude at the support points of the owned cells, over all ranks.
    template <int dim>
    double largest_magnitude(const LinearElasticProblem<dim>   &problem,
                             const PETScWrappers::MPI::Vector &ghosted)
    {
      const Quadrature<dim> support(problem.fe->get_unit_support_points());
      FEValues<dim>         fe_values(*problem.mapping, *problem.fe, support, update_values);
      std::vector<Vector<double>> values(support.size(), Vector<double>(dim));
      double                      largest = 0;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values.get_function_values(ghosted, values);
            for (const auto &v : values)
              largest = std::max(largest, v.l2_norm());
          }
      return Utilities::MPI::max(largest, problem.communicator);
    }
  } // namespace

  template <int dim>
  std::string write_mode_shapes(const LinearElasticProblem<dim>               &problem,
                                const std::vector<PETScWrappers::MPI::Vector> &modes,
                                const std::string                             &directory)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(problem.dof_handler);
    const std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    std::vector<PETScWrappers::MPI::Vector> scaled;
    scaled.reserve(modes.size()); // DataOut keeps references
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        scaled.emplace_back(problem.locally_owned_dofs, problem.locally_relevant_dofs,
                            problem.communicator);
        scaled.back() = modes[m];
        const double largest = largest_magnitude(problem, scaled.back());
        PETScWrappers::MPI::Vector owned(modes[m]);
        if (largest > 0)
          owned /= largest;
        scaled.back() = owned;
        data_out.add_data_vector(scaled.back(),
                                 std::vector<std::string>(dim, "mode_" + std::to_string(m + 1)),
                                 DataOut<dim>::type_dof_data, interpretation);
      }
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
    const bool hypercube = problem.triangulation.all_reference_cells_are_hyper_cube();
    data_out.build_patches(*problem.mapping, hypercube ? problem.parameters.element_degree : 1);

    DataOutBase::DataOutFilter filter(DataOutBase::DataOutFilterFlags(true, true));
    data_out.write_filtered_data(filter);
    const std::string h5      = "fields.h5";
    const std::string partial = directory + "/" + h5 + ".partial";
    data_out.write_hdf5_parallel(filter, partial, problem.communicator);
    std::vector<XDMFEntry> entries{data_out.create_xdmf_entry(filter, h5, 0., problem.communicator)};
    const std::string      xdmf = directory + "/fields.xdmf";
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

  template std::string write_mode_shapes<2>(const LinearElasticProblem<2> &,
                                            const std::vector<PETScWrappers::MPI::Vector> &,
                                            const std::string &);
  template std::string write_mode_shapes<3>(const LinearElasticProblem<3> &,
                                            const std::vector<PETScWrappers::MPI::Vector> &,
                                            const std::string &);
} // namespace compliant
