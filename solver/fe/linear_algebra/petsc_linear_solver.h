// Solves K x = f with PETSc: CG + GAMG with the rigid-body modes as near null space (what makes
// AMG work for elasticity), or MUMPS LU. Raw PETSc because deal.II 9.4 has no GAMG wrapper.
#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscpc.h>

#include "linear_algebra/solver_method.h"

#include <string>
#include <vector>

namespace compliant
{
  struct LinearSolverSettings
  {
    SolverMethod method = SolverMethod::cg_amg; // or direct
    double      relative_tolerance = 1e-10;
    unsigned    max_iterations     = 2000;
    std::string petsc_options;
  };

  // Returns the iteration count; throws std::runtime_error with PETSc's reason on failure.
  // block_size: DoFs per node when a node's components are numbered together (dim for
  // FESystem(FE_Q, dim)); GAMG then aggregates nodes instead of single DoFs.
  // kept_preconditioner: if given, receives the set-up preconditioner (a reference the caller
  // owns and destroys with PCDestroy), to serve another solve of the same matrix.
  unsigned int solve_linear_system(dealii::PETScWrappers::MPI::SparseMatrix              &matrix,
                                   dealii::PETScWrappers::MPI::Vector                    &solution,
                                   const dealii::PETScWrappers::MPI::Vector              &rhs,
                                   std::vector<dealii::PETScWrappers::MPI::Vector>       near_null_space,
                                   const LinearSolverSettings                            &settings,
                                   unsigned int                                          block_size = 1,
                                   PC                                                   *kept_preconditioner = nullptr);

  // Makes pc a PETSc GAMG preconditioner for the matrix (already the PC's operator) with the given
  // near null space (made orthonormal here) and block size; extra options (e.g.
  // '-pc_gamg_threshold 0.02') apply. Set-up happens at the first use.
  void configure_gamg(PC pc, dealii::PETScWrappers::MPI::SparseMatrix &matrix,
                      std::vector<dealii::PETScWrappers::MPI::Vector> near_null_space,
                      unsigned int block_size, const std::string &petsc_options);
  // 'Linear solver/PETSc options' into PETSc's (global) options database, for the solvers set
  // up after it; nothing if empty. Throws std::runtime_error if PETSc cannot read them.
  void insert_petsc_options(const std::string &petsc_options);
  // Number of negative eigenvalues of a symmetric matrix: the inertia of its LDL^T factor
  // (Sylvester's law), from MUMPS. Throws std::runtime_error if PETSc cannot give it.
  unsigned int count_negative_eigenvalues(dealii::PETScWrappers::MPI::SparseMatrix &matrix);
} // namespace compliant
