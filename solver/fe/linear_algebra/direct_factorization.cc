#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_check.h"

#include <deal.II/base/mpi.h>

#include <stdexcept>
#include <string>

namespace compliant
{
  namespace
  {
    const PetscErrorCheck check("direct factorization");
  } // namespace

  DirectFactorization::~DirectFactorization()
  {
    if (ksp != nullptr)
      KSPDestroy(&ksp);
  }

  void DirectFactorization::factor(dealii::PETScWrappers::MPI::SparseMatrix &matrix, const bool symmetric_matrix,
                                   const bool with_options, const bool inertia)
  {
    Mat        A = matrix;
    const bool kind_kept = ksp != nullptr && factored == A && symmetric == symmetric_matrix &&
                           with_inertia == (symmetric_matrix && inertia);
    if (!kind_kept && ksp != nullptr)
      KSPDestroy(&ksp);
    int failed = 0;
    try
      {
        failed = factor_once(matrix, symmetric_matrix, with_options, inertia);
      }
    catch (...)
      {
        KSPDestroy(&ksp); // a half-built solver is not kept for the next call
        throw;
      }
    if (failed != 0)
      {
        KSPDestroy(&ksp); // a failed factor is not kept for the next call
        // The kept analysis (ordering, scaling, workspace) was made for earlier values: once
        // more from scratch before giving up.
        if (kind_kept)
          return factor(matrix, symmetric_matrix, with_options, inertia);
        throw std::runtime_error("the factorization failed (PETSc reason " + std::to_string(failed) +
                                 "): the matrix is singular, or MUMPS ran out of workspace");
      }
  }

  int DirectFactorization::factor_once(dealii::PETScWrappers::MPI::SparseMatrix &matrix, const bool symmetric_matrix,
                                       const bool with_options, const bool inertia)
  {
    Mat A = matrix;
    PC  pc;
    if (ksp != nullptr)
      {
        // New values on the kept pattern: PCSetUp sees the same nonzero state and refactors
        // numerically on MUMPS's existing analysis.
        check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
        check(KSPGetPC(ksp, &pc), "KSPGetPC");
      }
    else
      {
        symmetric    = symmetric_matrix;
        with_inertia = symmetric && inertia;
        factored     = A;
        if (symmetric)
          check(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(symmetric)");
        check(KSPCreate(matrix.get_mpi_communicator(), &ksp), "KSPCreate");
        check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
        check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
        check(KSPGetPC(ksp, &pc), "KSPGetPC");
        check(PCSetType(pc, symmetric ? PCCHOLESKY : PCLU), "PCSetType");
        check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
        if (with_inertia)
          {
            Mat factor;
            check(PCFactorSetUpMatSolverType(pc), "PCFactorSetUpMatSolverType");
            check(PCFactorGetMatrix(pc, &factor), "PCFactorGetMatrix");
            check(MatMumpsSetIcntl(factor, 13, 1), "MatMumpsSetIcntl(13)"); // inertia over all ranks
            check(MatMumpsSetIcntl(factor, 24, 1), "MatMumpsSetIcntl(24)"); // null pivots, which the inertia needs
          }
        if (with_options)
          check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
      }
    check(KSPSetUp(ksp), "KSPSetUp (factorization)");
    PCFailedReason reason;
    check(PCGetFailedReason(pc, &reason), "PCGetFailedReason");
    // The reason is per rank: every rank fails, or none.
    return dealii::Utilities::MPI::max(reason != PC_NOERROR ? static_cast<int>(reason) : 0,
                                       matrix.get_mpi_communicator());
  }

  void DirectFactorization::solve(dealii::PETScWrappers::MPI::Vector &x, const dealii::PETScWrappers::MPI::Vector &b) const
  {
    solve(static_cast<Vec>(x), static_cast<Vec>(b));
  }

  void DirectFactorization::solve(Vec x, Vec b) const
  {
    check(KSPSolve(ksp, b, x), "KSPSolve");
    KSPConvergedReason reason;
    KSPGetConvergedReason(ksp, &reason);
    if (reason < 0)
      throw std::runtime_error("the direct solve failed (PETSc reason " + std::to_string(reason) + ")");
  }

  void DirectFactorization::solve_transpose(dealii::PETScWrappers::MPI::Vector       &x,
                                            const dealii::PETScWrappers::MPI::Vector &b) const
  {
    check(KSPSolveTranspose(ksp, static_cast<Vec>(b), static_cast<Vec>(x)), "KSPSolveTranspose");
    KSPConvergedReason reason;
    KSPGetConvergedReason(ksp, &reason);
    if (reason < 0)
      throw std::runtime_error("the transposed direct solve failed (PETSc reason " + std::to_string(reason) + ")");
  }

  unsigned int DirectFactorization::negative_eigenvalues() const
  {
    if (!with_inertia)
      throw std::logic_error("the inertia needs a symmetric (LDL^T) factorization made with inertia = true");
    PC       pc;
    Mat      factor;
    PetscInt negative = 0, zero = 0, positive = 0;
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    check(PCFactorGetMatrix(pc, &factor), "PCFactorGetMatrix");
    check(MatGetInertia(factor, &negative, &zero, &positive), "MatGetInertia");
    return negative;
  }
} // namespace compliant
