#include "quantities/point_stress.h"

#include "quantities/point_location.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"
#include "quantities/named_points.h"

#include <algorithm>
#include <cmath>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    std::map<std::string, Point<dim>> stress_points(const CaseParameters &p)
    {
      return parse_named_points<dim>(p.stress_points, p.geometry_parameters, "Quantities/Stress points");
    }

    // Components in output order: xx, yy, zz, xy (2D); xx, yy, zz, xy, xz, yz (3D).
    template <int dim>
    constexpr unsigned int n_components = dim == 2 ? 4 : 6;
    const char *component_name[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};
    const unsigned int component_index[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

    // The full 3 x 3 stress of a point (sigma_zz of 2D models in place) from the displacement
    // gradient and, for mixed formulations, the pressure.
    template <class Problem, int dim = Problem::dimension>
    SymmetricTensor<2, 3> stress_at(const Problem &problem, const Tensor<2, dim> &grad_u,
                                    const types::material_id material_id, const double pressure)
    {
      double     sigma_zz = 0;
      const auto sigma    = problem.cauchy_stress(grad_u, problem.materials.at(material_id), pressure, sigma_zz);
      SymmetricTensor<2, 3> full;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          full[i][j] = sigma[i][j];
      if (dim == 2)
        full[2][2] = sigma_zz;
      return full;
    }

    double von_mises_of(const SymmetricTensor<2, 3> &s)
    {
      const SymmetricTensor<2, 3> deviator = s - trace(s) / 3 * unit_symmetric_tensor<3>();
      return std::sqrt(1.5 * (deviator * deviator));
    }

    // L2 projection of the stress components onto continuous scalar elements of the
    // displacement's degree: M s_c = (phi, sigma_c) per component c, CG with Jacobi.
    template <class Problem, int dim = Problem::dimension>
    struct RecoveredStress
    {
      explicit RecoveredStress(const Problem &problem)
        : dofs(problem.triangulation)
      {
        const unsigned int degree = problem.parameters.element_degree;
        if (problem.triangulation.all_reference_cells_are_hyper_cube())
          fe = std::make_unique<FE_Q<dim>>(degree);
        else
          fe = std::make_unique<FE_SimplexP<dim>>(degree);
        dofs.distribute_dofs(*fe);
        const IndexSet owned = dofs.locally_owned_dofs();
        IndexSet       relevant;
        DoFTools::extract_locally_relevant_dofs(dofs, relevant);
        AffineConstraints<double> hanging(relevant);
        DoFTools::make_hanging_node_constraints(dofs, hanging);
        hanging.close();
        DynamicSparsityPattern dsp(relevant);
        DoFTools::make_sparsity_pattern(dofs, dsp, hanging, false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned, problem.communicator, relevant);
        PETScWrappers::MPI::SparseMatrix mass;
        mass.reinit(owned, owned, dsp, problem.communicator);
        std::vector<PETScWrappers::MPI::Vector> rhs(n_components<dim>,
                                                    PETScWrappers::MPI::Vector(owned, problem.communicator));

        // Integration = reduced: the projection keeps the full rule (its p-point part alone would
        // leave the mass matrix singular, and the rule's conditioning would follow 1 / e).
        const Quadrature<dim> quadrature = problem.parameters.reduced_integration ?
                                             Quadrature<dim>(QGauss<dim>(problem.fe->degree + 1)) :
                                             *problem.quadrature;
        FEValues<dim> displacement_values(*problem.mapping, *problem.fe, quadrature, update_gradients | update_values);
        FEValues<dim> scalar_values(*problem.mapping, *fe, quadrature, update_values | update_JxW_values);
        const bool    has_pressure = problem.fe->n_components() > dim;
        const FEValuesExtractors::Vector u(0);
        const FEValuesExtractors::Scalar pressure(has_pressure ? dim : 0);
        std::vector<Tensor<2, dim>>      grad(quadrature.size());
        std::vector<double>              p_values(quadrature.size(), 0.0);
        const unsigned int               n = fe->n_dofs_per_cell();
        FullMatrix<double>               cell_mass(n, n);
        std::vector<Vector<double>>      cell_rhs(n_components<dim>, Vector<double>(n));
        std::vector<types::global_dof_index> local_dofs(n);
        for (const auto &cell : problem.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              const typename DoFHandler<dim>::active_cell_iterator scalar_cell(&problem.triangulation, cell->level(),
                                                                               cell->index(), &dofs);
              displacement_values.reinit(cell);
              scalar_values.reinit(scalar_cell);
              displacement_values[u].get_function_gradients(problem.solution, grad);
              if (has_pressure)
                displacement_values[pressure].get_function_values(problem.solution, p_values);
              cell_mass = 0;
              for (auto &r : cell_rhs)
                r = 0;
              for (unsigned int k = 0; k < quadrature.size(); ++k)
                {
                  const auto   sigma = stress_at(problem, grad[k], cell->material_id(), p_values[k]);
                  const double JxW   = scalar_values.JxW(k);
                  for (unsigned int i = 0; i < n; ++i)
                    {
                      const double phi_i = scalar_values.shape_value(i, k);
                      for (unsigned int j = 0; j < n; ++j)
                        cell_mass(i, j) += phi_i * scalar_values.shape_value(j, k) * JxW;
                      for (unsigned int c = 0; c < n_components<dim>; ++c)
                        cell_rhs[c](i) += phi_i * sigma[component_index[c][0]][component_index[c][1]] * JxW;
                    }
                }
              scalar_cell->get_dof_indices(local_dofs);
              hanging.distribute_local_to_global(cell_mass, local_dofs, mass);
              for (unsigned int c = 0; c < n_components<dim>; ++c)
                hanging.distribute_local_to_global(cell_rhs[c], local_dofs, rhs[c]);
            }
        mass.compress(VectorOperation::add);
        for (auto &r : rhs)
          r.compress(VectorOperation::add);

        PETScWrappers::PreconditionJacobi jacobi(mass);
        for (unsigned int c = 0; c < n_components<dim>; ++c)
          {
            PETScWrappers::MPI::Vector x(owned, problem.communicator);
            // The mass matrix is well conditioned (Jacobi-preconditioned CG converges in a few
            // dozen steps whatever the mesh size); 1e-12 leaves the projection error alone.
            SolverControl control(1000, std::max(1e-12 * rhs[c].l2_norm(), 1e-300));
            PETScWrappers::SolverCG cg(control, problem.communicator);
            if (rhs[c].l2_norm() > 0)
              cg.solve(mass, x, rhs[c], jacobi);
            hanging.distribute(x);
            components.emplace_back(owned, relevant, problem.communicator);
            components.back() = x;
          }
      }

      SymmetricTensor<2, 3> at(const typename DoFHandler<dim>::active_cell_iterator &cell,
                               const Mapping<dim> &mapping, const Point<dim> &unit_point) const
      {
        const typename DoFHandler<dim>::active_cell_iterator scalar_cell(&cell->get_triangulation(), cell->level(),
                                                                         cell->index(), &dofs);
        FEValues<dim> values(mapping, *fe, Quadrature<dim>(unit_point), update_values);
        values.reinit(scalar_cell);
        SymmetricTensor<2, 3> sigma;
        std::vector<double>   v(1);
        for (unsigned int c = 0; c < n_components<dim>; ++c)
          {
            values.get_function_values(components[c], v);
            sigma[component_index[c][0]][component_index[c][1]] = v[0];
          }
        return sigma;
      }

      std::unique_ptr<FiniteElement<dim>>      fe;
      DoFHandler<dim>                          dofs;
      std::vector<PETScWrappers::MPI::Vector>  components; // ghosted
    };
  } // namespace

  template <class Problem>
  void validate_point_stresses(const Problem &problem)
  {
    constexpr int dim = Problem::dimension;
    for (const auto &[name, point] : stress_points<dim>(problem.parameters))
      {
        const double owners = Utilities::MPI::sum(
          owned_cell_around(problem.point_mapping(), problem.dof_handler, point).first.state() == IteratorState::valid ? 1.0 : 0.0,
          problem.communicator);
        if (owners == 0)
          throw std::invalid_argument("Quantities/Stress points: point '" + name + "' lies outside the mesh");
      }
  }

  template <class Problem>
  void add_point_stresses(const Problem &problem, Quantities &q)
  {
    constexpr int dim    = Problem::dimension;
    const auto    points = stress_points<dim>(problem.parameters);
    if (points.empty())
      return;
    const RecoveredStress<Problem> recovered(problem);
    const bool                     has_pressure = problem.fe->n_components() > dim;
    for (const auto &[name, point] : points)
      {
        // Summed over the ranks that own a cell around the point and averaged: on a
        // distributed mesh a point on a rank boundary may be claimed twice.
        SymmetricTensor<2, 3> smooth, raw;
        double                owners = 0;
        const auto [cell, unit_point] = owned_cell_around(problem.point_mapping(), problem.dof_handler, point);
        if (cell.state() == IteratorState::valid)
          {
            owners = 1;
            smooth = recovered.at(cell, *problem.mapping, unit_point);
            FEValues<dim> values(*problem.mapping, *problem.fe, Quadrature<dim>(unit_point),
                                 update_values | update_gradients);
            values.reinit(cell);
            std::vector<Tensor<2, dim>> grad(1);
            std::vector<double>         p_value(1, 0.0);
            values[FEValuesExtractors::Vector(0)].get_function_gradients(problem.solution, grad);
            if (has_pressure)
              values[FEValuesExtractors::Scalar(dim)].get_function_values(problem.solution, p_value);
            raw = stress_at(problem, grad[0], cell->material_id(), p_value[0]);
          }
        owners = Utilities::MPI::sum(owners, problem.communicator);
        smooth = Utilities::MPI::sum(smooth, problem.communicator) / owners;
        raw    = Utilities::MPI::sum(raw, problem.communicator) / owners;
        for (unsigned int c = 0; c < n_components<dim>; ++c)
          {
            const auto key = "stress_" + name + "_" + component_name[c];
            q[key]          = smooth[component_index[c][0]][component_index[c][1]];
            q[key + "_raw"] = raw[component_index[c][0]][component_index[c][1]];
          }
        q["von_mises_" + name]          = von_mises_of(smooth);
        q["von_mises_" + name + "_raw"] = von_mises_of(raw);
        auto principal = eigenvalues(smooth);
        std::sort(principal.begin(), principal.end(), std::greater<double>());
        for (unsigned int i = 0; i < 3; ++i)
          q["principal_stress_" + name + "_" + std::to_string(i + 1)] = principal[i];
      }
  }

  template void validate_point_stresses(const LinearElasticProblem<2> &);
  template void validate_point_stresses(const LinearElasticProblem<3> &);
  template void validate_point_stresses(const FiniteStrainProblem<2> &);
  template void validate_point_stresses(const FiniteStrainProblem<3> &);
  template void add_point_stresses(const LinearElasticProblem<2> &, Quantities &);
  template void add_point_stresses(const LinearElasticProblem<3> &, Quantities &);
  template void add_point_stresses(const FiniteStrainProblem<2> &, Quantities &);
  template void add_point_stresses(const FiniteStrainProblem<3> &, Quantities &);
} // namespace compliant
