#include "linear_algebra/two_level_solver.h"

#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_check.h"

#include <petscksp.h>

#include <stdexcept>

#include <string>

namespace compliant
{
  namespace
  {
    const PetscErrorCheck check("two-level solver");

    // The coarse level: the residual zeroed where the coarse constraints fix the DoF (the
    // condensed factor then returns zero there), then the factor's back-substitution.
    PetscErrorCode apply_coarse_factor(PC pc, Vec b, Vec x)
    {
      void *context = nullptr;
      PCShellGetContext(pc, &context);
      const auto &system = *static_cast<const TwoLevelSystem *>(context);
      Vec         masked;
      VecDuplicate(b, &masked);
      VecCopy(b, masked);
      for (const auto index : system.coarse_constrained)
        VecSetValue(masked, static_cast<PetscInt>(index), 0., INSERT_VALUES);
      VecAssemblyBegin(masked);
      VecAssemblyEnd(masked);
      try
        {
          system.coarse_factor->solve(x, masked);
        }
      catch (const std::runtime_error &)
        {
          VecDestroy(&masked);
          return PETSC_ERR_LIB;
        }
      VecDestroy(&masked);
      return 0;
    }

    // Smoothing per side of the V-cycle: one symmetric Gauss-Seidel sweep per rank (symmetric, so
    // the V-cycle is, as CG needs; no eigenvalue estimate to set up). Measured on the Lame sphere's
    // refined P2 tetrahedra (27.8k DoFs, cases/verification/error_estimates.py): 7 iterations to
    // 1e-4 and 0.25 s, where Chebyshev-Jacobi of degree 3 took 7 and 0.55 s with its set-up, and
    // two sweeps 5 iterations and 0.29 s.
    constexpr PetscInt smoothing_sweeps = 1;
  } // namespace

  TwoLevelResult solve_two_level(const TwoLevelSystem &system, const dealii::PETScWrappers::MPI::Vector &b,
                                 dealii::PETScWrappers::MPI::Vector &x, const double reduction,
                                 const unsigned int max_iterations)
  {
    Mat fine   = *system.fine_matrix;
    Mat coarse = *system.coarse_matrix;
    KSP ksp    = nullptr;
    PC  pc, coarse_pc, smoother_pc;
    KSP coarse_ksp, smoother;
    check(KSPCreate(system.fine_matrix->get_mpi_communicator(), &ksp), "KSPCreate");
    TwoLevelResult result;
    try
      {
        check(KSPSetOperators(ksp, fine, fine), "KSPSetOperators");
        check(KSPSetType(ksp, KSPCG), "KSPSetType(cg)");
        check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
        check(KSPSetInitialGuessNonzero(ksp, PETSC_TRUE), "KSPSetInitialGuessNonzero");
        check(KSPSetTolerances(ksp, reduction, 0., PETSC_DEFAULT, max_iterations), "KSPSetTolerances");
        check(KSPConvergedDefaultSetUIRNorm(ksp), "KSPConvergedDefaultSetUIRNorm"); // relative to |b - A x0|
        check(KSPGetPC(ksp, &pc), "KSPGetPC");
        check(PCSetType(pc, PCMG), "PCSetType(mg)");
        check(PCMGSetLevels(pc, 2, nullptr), "PCMGSetLevels");
        check(PCMGSetType(pc, PC_MG_MULTIPLICATIVE), "PCMGSetType");
        check(PCMGSetCycleType(pc, PC_MG_CYCLE_V), "PCMGSetCycleType");
        check(PCMGSetInterpolation(pc, 1, *system.prolongation), "PCMGSetInterpolation");

        check(PCMGGetCoarseSolve(pc, &coarse_ksp), "PCMGGetCoarseSolve");
        check(KSPSetOperators(coarse_ksp, coarse, coarse), "KSPSetOperators(coarse)");
        check(KSPSetType(coarse_ksp, KSPPREONLY), "KSPSetType(coarse)");
        check(KSPGetPC(coarse_ksp, &coarse_pc), "KSPGetPC(coarse)");
        check(PCSetType(coarse_pc, PCSHELL), "PCSetType(shell)");
        check(PCShellSetContext(coarse_pc, const_cast<TwoLevelSystem *>(&system)), "PCShellSetContext");
        check(PCShellSetApply(coarse_pc, apply_coarse_factor), "PCShellSetApply");

        check(PCMGGetSmoother(pc, 1, &smoother), "PCMGGetSmoother");
        check(KSPSetOperators(smoother, fine, fine), "KSPSetOperators(smoother)");
        check(KSPSetType(smoother, KSPRICHARDSON), "KSPSetType(richardson)");
        check(KSPSetTolerances(smoother, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, smoothing_sweeps),
              "KSPSetTolerances(smoother)");
        check(KSPSetNormType(smoother, KSP_NORM_NONE), "KSPSetNormType(smoother)");
        check(KSPGetPC(smoother, &smoother_pc), "KSPGetPC(smoother)");
        check(PCSetType(smoother_pc, PCSOR), "PCSetType(sor)");
        check(PCSORSetSymmetric(smoother_pc, SOR_LOCAL_SYMMETRIC_SWEEP), "PCSORSetSymmetric");

        check(KSPSetUp(ksp), "KSPSetUp");
        {
          dealii::PETScWrappers::MPI::Vector residual(b);
          system.fine_matrix->residual(residual, x, b);
          result.initial_residual = residual.l2_norm();
        }
        check(KSPSolve(ksp, b, x), "KSPSolve");
        PetscInt           iterations = 0;
        PetscReal          norm       = 0;
        KSPConvergedReason reason;
        KSPGetIterationNumber(ksp, &iterations);
        KSPGetResidualNorm(ksp, &norm);
        KSPGetConvergedReason(ksp, &reason);
        result.iterations     = static_cast<unsigned int>(iterations);
        result.final_residual = norm;
        if (reason < 0)
          throw std::runtime_error("two-level CG did not converge in " + std::to_string(iterations) +
                                   " iterations (PETSc reason " + std::to_string(reason) + ")");
      }
    catch (...)
      {
        KSPDestroy(&ksp);
        throw;
      }
    KSPDestroy(&ksp);
    return result;
  }
} // namespace compliant
