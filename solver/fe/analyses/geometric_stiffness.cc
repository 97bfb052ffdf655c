#include "analyses/geometric_stiffness.h"

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  void assemble_geometric_stiffness(const LinearElasticProblem<dim> &problem,
                                    PETScWrappers::MPI::SparseMatrix &geometric)
  {
    geometric.reinit(problem.system_matrix);
    geometric = 0;
    const auto                      &fe = *problem.fe;
    FEValues<dim>                    fe_values(*problem.mapping, fe, *problem.quadrature,
                                               update_gradients | update_values | update_JxW_values);
    const unsigned int               n = fe.n_dofs_per_cell(), n_q = fe_values.n_quadrature_points;
    const bool                       has_pressure = fe.n_components() > dim;
    const FEValuesExtractors::Vector u(0);
    const FEValuesExtractors::Scalar pressure(has_pressure ? dim : 0);
    std::vector<Tensor<2, dim>>      grad_u(n_q);
    std::vector<double>              p_q(n_q, 0.);
    FullMatrix<double>               cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(problem.solution, grad_u);
          if (has_pressure)
            fe_values[pressure].get_function_values(problem.solution, p_q);
          const Material &material = problem.materials.at(cell->material_id());
          cell_matrix              = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            {
              double     sigma_zz;
              const auto sigma = problem.cauchy_stress(grad_u[q], material, p_q[q], sigma_zz);
              const double dx  = fe_values.JxW(q) * problem.thickness;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci = fe.system_to_component_index(i).first;
                  if (ci >= dim)
                    continue;
                  const Tensor<1, dim> s_grad_i = sigma * fe_values.shape_grad_component(i, q, ci);
                  for (unsigned int j = 0; j < n; ++j)
                    if (fe.system_to_component_index(j).first == ci)
                      cell_matrix(i, j) += s_grad_i * fe_values.shape_grad_component(j, q, ci) * dx;
                }
            }
          cell->get_dof_indices(dofs);
          // Condensed like the stiffness (hanging nodes); the prescribed values play no part.
          problem.constraints.distribute_local_to_global(cell_matrix, dofs, geometric);
        }
    geometric.compress(VectorOperation::add);
    // The diagonal that condensation put on constrained rows out: such a DoF does not move in a
    // buckling mode, and a finite entry there would give a spurious factor.
    std::vector<types::global_dof_index> constrained;
    for (const auto i : problem.locally_owned_dofs)
      if (problem.constraints.is_constrained(i))
        constrained.push_back(i);
    geometric.clear_rows(constrained, 0.);
  }

  template void assemble_geometric_stiffness(const LinearElasticProblem<2> &, PETScWrappers::MPI::SparseMatrix &);
  template void assemble_geometric_stiffness(const LinearElasticProblem<3> &, PETScWrappers::MPI::SparseMatrix &);
} // namespace compliant
