// CG on a fine system preconditioned by two levels: symmetric Gauss-Seidel smoothing on the fine matrix
// and an exact coarse correction P K_c^-1 P^T through the factor a coarser model already has.
// The error estimates' once-refined model (triangles and tetrahedra at their highest degree) is
// solved this way from the coarse model's solution: a few fine matrix products and coarse
// back-substitutions instead of a second factorization, 2^dim times larger.
#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <vector>

namespace compliant
{
  class DirectFactorization; // linear_algebra/direct_factorization.h

  struct TwoLevelSystem
  {
    const dealii::PETScWrappers::MPI::SparseMatrix *fine_matrix   = nullptr; // constraints condensed
    const dealii::PETScWrappers::MPI::SparseMatrix *prolongation  = nullptr; // fine rows, coarse columns
    const dealii::PETScWrappers::MPI::SparseMatrix *coarse_matrix = nullptr; // the factored one
    const DirectFactorization                      *coarse_factor = nullptr;
    // Owned coarse DoFs that the coarse constraints fix: the coarse correction is zero there.
    std::vector<dealii::types::global_dof_index> coarse_constrained;
  };

  struct TwoLevelResult
  {
    unsigned int iterations       = 0;
    double       initial_residual = 0; // |b - A x0|
    double       final_residual   = 0;
  };

  // Solves A x = b from the x given until |b - A x| <= reduction |b - A x0|; throws
  // std::runtime_error if max_iterations do not get there (the caller falls back to MUMPS).
  TwoLevelResult solve_two_level(const TwoLevelSystem &system, const dealii::PETScWrappers::MPI::Vector &b,
                                 dealii::PETScWrappers::MPI::Vector &x, double reduction,
                                 unsigned int max_iterations);
} // namespace compliant
