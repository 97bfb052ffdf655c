// A field of one discretization carried to another of the same mesh at a higher degree (Q_p into
// Q_p+1, P1 into P2, with the mixed formulation's discontinuous P_p-1 pressure into P_p): exact,
// since V_p lies in V_p+1. The error estimates' enriched model starts
// its iterative solve from the degree-p solution this way, so the solve only has to find the
// (small) difference.
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "discretization/discretization.h"

namespace compliant
{
  // Interpolates `field` (ghosted, on from's DoFs) into `result` (owned DoFs of `to`). Both must
  // be built from the same mesh and partition: the active cells are walked side by side and must
  // agree cell by cell (id and centre); false, with result untouched, where they do not (another
  // refinement, another partition, other elements).
  template <int dim>
  bool interpolate_to_finer_degree(const Discretization<dim>                &from,
                                   const dealii::PETScWrappers::MPI::Vector &field,
                                   const Discretization<dim>                &to,
                                   dealii::PETScWrappers::MPI::Vector       &result);
} // namespace compliant
