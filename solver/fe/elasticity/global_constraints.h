// Constraints known on every rank, for couplings between DoFs of cells that lie on different
// ranks (pin joints tie separate bodies, which METIS may put on different ranks) and for the
// homogeneous constraints of a modal analysis. The triangulation is shared, so every rank knows
// every DoF; only the constraint lines have to be gathered.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "elasticity/linear_elastic_problem.h"

namespace compliant
{
  // The problem's (closed) constraint lines of all ranks, on every rank, not yet closed. With
  // homogeneous = true the prescribed values are dropped: every Dirichlet boundary is held
  // fixed (what a modal analysis of a supported structure needs).
  template <int dim>
  dealii::AffineConstraints<double> gather_constraints(const LinearElasticProblem<dim> &problem,
                                                       bool                             homogeneous);

  // Closes the constraints, makes them the problem's, and rebuilds the sparsity pattern and the
  // system matrix for them. Returns the (distributed) sparsity pattern for further matrices.
  template <int dim>
  dealii::DynamicSparsityPattern install_constraints(LinearElasticProblem<dim>          &problem,
                                                     dealii::AffineConstraints<double> &&constraints);
} // namespace compliant
