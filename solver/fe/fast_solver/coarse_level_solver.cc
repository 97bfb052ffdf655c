#include "fast_solver/coarse_level_solver.h"

#include "linear_algebra/petsc_linear_solver.h"

#include <algorithm>
#include <stdexcept>

namespace compliant::fast_solver
{
  namespace
  {
    void check(const PetscErrorCode ierr, const char *what)
    {
      if (ierr != 0)
        throw std::runtime_error(std::string("coarse level solver: PETSc error in ") + what);
    }
  } // namespace

  CoarseLevelSolver::CoarseLevelSolver(dealii::PETScWrappers::MPI::SparseMatrix         &matrix,
                                       std::vector<dealii::PETScWrappers::MPI::Vector> rigid_body_modes,
                                       const unsigned int block_size, const bool direct,
                                       const double relative_tolerance, const std::string &petsc_options)
  {
    const auto owned = matrix.locally_owned_range_indices();
    rhs.reinit(owned, matrix.get_mpi_communicator());
    correction.reinit(owned, matrix.get_mpi_communicator());
    PC pc;
    check(KSPCreate(matrix.get_mpi_communicator(), &ksp), "KSPCreate");
    check(KSPSetOperators(ksp, matrix, matrix), "KSPSetOperators");
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    if (direct)
      {
        check(KSPSetType(ksp, KSPPREONLY), "KSPSetType(preonly)");
        check(PCSetType(pc, PCLU), "PCSetType(lu)");
        check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
        check(KSPSetUp(ksp), "KSPSetUp (MUMPS factorization)");
        return;
      }
    configure_gamg(pc, matrix, std::move(rigid_body_modes), block_size, petsc_options);
    check(PCSetFromOptions(pc), "PCSetFromOptions");
    if (relative_tolerance > 0)
      {
        check(KSPSetType(ksp, KSPCG), "KSPSetType(cg)");
        check(KSPSetTolerances(ksp, relative_tolerance, 1e-300, PETSC_DEFAULT, 100),
              "KSPSetTolerances");
        check(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
      }
    else
      check(KSPSetType(ksp, KSPPREONLY), "KSPSetType(preonly)");
    check(KSPSetUp(ksp), "KSPSetUp (GAMG set-up)");
  }

  CoarseLevelSolver::~CoarseLevelSolver()
  {
    if (ksp)
      KSPDestroy(&ksp);
  }

  void CoarseLevelSolver::operator()(const unsigned int, VectorType &dst, const VectorType &src) const
  {
    // Both vectors number the same owned DoFs in the same order: copy the local parts.
    const unsigned int n = src.locally_owned_size();
    {
      PetscScalar *values;
      VecGetArray(rhs, &values);
      for (unsigned int i = 0; i < n; ++i)
        values[i] = src.local_element(i);
      VecRestoreArray(rhs, &values);
    }
    check(KSPSolve(ksp, rhs, correction), "KSPSolve");
    PetscInt iterations = 0;
    KSPGetIterationNumber(ksp, &iterations);
    total_iterations += std::max<PetscInt>(iterations, 1);
    const PetscScalar *values;
    VecGetArrayRead(correction, &values);
    for (unsigned int i = 0; i < n; ++i)
      dst.local_element(i) = values[i];
    VecRestoreArrayRead(correction, &values);
  }
} // namespace compliant::fast_solver
