// Consistent mass matrix M_ij = int rho phi_i . phi_j dV (times the thickness in 2D), condensed
// with the problem's constraints, and the rigid translations used for effective modal masses.
#pragma once

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "elasticity/linear_elastic_problem.h"

namespace compliant
{
  // Density is the material's, already in the case's unit system (t/mm^3 with mm-N-MPa), so
  // K x = omega^2 M x gives omega in rad/s in both systems. Constrained rows get a zero diagonal:
  // they become infinite eigenvalues instead of spurious finite ones (deal.II step-36 discusses
  // the alternative of a large diagonal ratio).
  template <int dim>
  void assemble_mass_matrix(const LinearElasticProblem<dim>         &problem,
                            const dealii::DynamicSparsityPattern    &sparsity,
                            dealii::PETScWrappers::MPI::SparseMatrix &mass);

  // int rho dV over the whole model (times the thickness in 2D): the physical mass, including
  // the part that sits on supports.
  template <int dim>
  double total_mass(const LinearElasticProblem<dim> &problem);

  // Unit rigid translation along `component`, 1 at every DoF of that component.
  template <int dim>
  dealii::PETScWrappers::MPI::Vector translation(const LinearElasticProblem<dim> &problem,
                                                 unsigned int                     component);
} // namespace compliant
