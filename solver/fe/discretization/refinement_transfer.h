// The prolongation from a model's DoFs to those of its once-refined twin (the same mesh built again
// with one more global refinement, the same element): column j of P is the fine field of coarse
// DoF j set to one, from the element's prolongation matrices, child by child. It carries a coarse
// solution to the refined mesh exactly (V_coarse lies in V_fine where the new vertices do not
// move) and is the interpolation of a two-level solver (linear_algebra/two_level_solver.h).
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>

#include "discretization/discretization.h"

namespace compliant
{
  // P with rows on fine's owned DoFs and columns on coarse's. Rows of DoFs that fine_constraints
  // fix are left empty (a coarse correction must not move them). The coarse mesh must be shared
  // (every rank holds every cell; the fine one may be distributed) and every fine cell a child of
  // an active coarse cell with the same vertices; false, P untouched, where they are not (a
  // distributed coarse mesh, another refinement).
  template <int dim>
  bool build_refinement_prolongation(const Discretization<dim>               &coarse,
                                     const Discretization<dim>               &fine,
                                     const dealii::AffineConstraints<double> &fine_constraints,
                                     dealii::PETScWrappers::MPI::SparseMatrix &prolongation);
} // namespace compliant
