// The geometric (initial-stress) stiffness of a prestressed state, K_sigma_ij = int grad N_i .
// sigma_0 . grad N_j (delta of their components) dV, sigma_0 the Cauchy stress of the linear
// solution: the matrix of linearized buckling, (K + lambda K_sigma) phi = 0. Assembled into a matrix
// of the stiffness matrix's layout; rows of constrained DoFs are left empty (their buckling factor
// is infinite) and so are the rows of a mixed element's pressure.
#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>

#include "elasticity/linear_elastic_problem.h"

namespace compliant
{
  template <int dim>
  void assemble_geometric_stiffness(const LinearElasticProblem<dim>          &problem,
                                    dealii::PETScWrappers::MPI::SparseMatrix &geometric);
} // namespace compliant
