#include "analyses/modal_mass_matrix.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  void assemble_mass_matrix(const LinearElasticProblem<dim>  &problem,
                            const DynamicSparsityPattern     &sparsity,
                            PETScWrappers::MPI::SparseMatrix &mass)
  {
    mass.reinit(problem.locally_owned_dofs, problem.locally_owned_dofs, sparsity,
                problem.communicator);
    // Gauss with degree + 1 points integrates phi_i phi_j exactly on affine cells.
    FEValues<dim> fe_values(*problem.mapping, *problem.fe, *problem.quadrature,
                            update_values | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    const unsigned int                   n = problem.fe->n_dofs_per_cell();
    FullMatrix<double>                   cell_matrix(n, n);
    std::vector<types::global_dof_index> dofs(n);
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const double rho = problem.materials.at(cell->material_id()).density;
          cell_matrix      = 0;
          for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
            {
              const double rho_JxW = rho * fe_values.JxW(q) * problem.thickness;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int ci = problem.fe->system_to_component_index(i).first;
                  if (ci >= dim)
                    continue; // the pressure of a mixed element carries no mass
                  for (unsigned int j = 0; j < n; ++j)
                    if (problem.fe->system_to_component_index(j).first == ci)
                      cell_matrix(i, j) += fe_values.shape_value(i, q) *
                                           fe_values.shape_value(j, q) * rho_JxW;
                }
            }
          cell->get_dof_indices(dofs);
          problem.constraints.distribute_local_to_global(cell_matrix, dofs, mass);
        }
    mass.compress(VectorOperation::add);
    for (const auto i : problem.locally_owned_dofs)
      if (problem.constraints.is_constrained(i))
        mass.set(i, i, 0.0);
    mass.compress(VectorOperation::insert);
  }

  template <int dim>
  double total_mass(const LinearElasticProblem<dim> &problem)
  {
    FEValues<dim> fe_values(*problem.mapping, *problem.fe, *problem.quadrature, update_JxW_values);
    double        mass = 0;
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          const double rho = problem.materials.at(cell->material_id()).density;
          for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
            mass += rho * fe_values.JxW(q) * problem.thickness;
        }
    return Utilities::MPI::sum(mass, problem.communicator);
  }

  template <int dim>
  PETScWrappers::MPI::Vector translation(const LinearElasticProblem<dim> &problem,
                                         const unsigned int               component)
  {
    PETScWrappers::MPI::Vector r(problem.locally_owned_dofs, problem.communicator);
    ComponentMask              mask(problem.fe->n_components(), false);
    mask.set(component, true);
    const IndexSet component_dofs = DoFTools::extract_dofs(problem.dof_handler, mask);
    for (const auto i : component_dofs)
      if (problem.locally_owned_dofs.is_element(i))
        r[i] = 1.0;
    r.compress(VectorOperation::insert);
    return r;
  }

  template void assemble_mass_matrix<2>(const LinearElasticProblem<2> &,
                                        const DynamicSparsityPattern &,
                                        PETScWrappers::MPI::SparseMatrix &);
  template void assemble_mass_matrix<3>(const LinearElasticProblem<3> &,
                                        const DynamicSparsityPattern &,
                                        PETScWrappers::MPI::SparseMatrix &);
  template double total_mass<2>(const LinearElasticProblem<2> &);
  template double total_mass<3>(const LinearElasticProblem<3> &);
  template PETScWrappers::MPI::Vector translation<2>(const LinearElasticProblem<2> &, unsigned int);
  template PETScWrappers::MPI::Vector translation<3>(const LinearElasticProblem<3> &, unsigned int);
} // namespace compliant
