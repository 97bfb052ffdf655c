#include "linear_algebra/petsc_linear_solver.h"

#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_check.h"

#include <petscksp.h>

#include <stdexcept>
#include <string>

namespace compliant
{
  namespace
  {
    const PetscErrorCheck check("linear solver");

    // MatNullSpaceCreate requires orthonormal vectors.
    void orthonormalize(std::vector<dealii::PETScWrappers::MPI::Vector> &modes)
    {
      for (unsigned int i = 0; i < modes.size(); ++i)
        {
          for (unsigned int j = 0; j < i; ++j)
            modes[i].add(-(modes[i] * modes[j]), modes[j]);
          modes[i] /= modes[i].l2_norm();
        }
    }

    // Sets the block size and the orthonormalized near null space on the matrix; returns the null
    // space object the caller destroys.
    MatNullSpace attach_near_null_space(Mat A, MPI_Comm comm,
                                        std::vector<dealii::PETScWrappers::MPI::Vector> &modes,
                                        const unsigned int block_size)
    {
      if (block_size > 1)
        check(MatSetBlockSize(A, block_size), "MatSetBlockSize");
      orthonormalize(modes);
      std::vector<Vec> vecs;
      for (auto &v : modes)
        vecs.push_back(v);
      MatNullSpace null_space = nullptr;
      check(MatNullSpaceCreate(comm, PETSC_FALSE, vecs.size(), vecs.data(), &null_space),
            "MatNullSpaceCreate");
      check(MatSetNearNullSpace(A, null_space), "MatSetNearNullSpace");
      return null_space;
    }
  } // namespace

  void configure_gamg(PC pc, dealii::PETScWrappers::MPI::SparseMatrix &matrix,
                      std::vector<dealii::PETScWrappers::MPI::Vector> near_null_space,
                      const unsigned int block_size, const std::string &petsc_options)
  {
    check(PCSetType(pc, PCGAMG), "PCSetType(gamg)");
    MatNullSpace null_space =
      attach_near_null_space(matrix, matrix.get_mpi_communicator(), near_null_space, block_size);
    MatNullSpaceDestroy(&null_space); // the matrix keeps its own reference
    insert_petsc_options(petsc_options);
  }

  unsigned int solve_linear_system(dealii::PETScWrappers::MPI::SparseMatrix        &matrix,
                                   dealii::PETScWrappers::MPI::Vector              &solution,
                                   const dealii::PETScWrappers::MPI::Vector        &rhs,
                                   std::vector<dealii::PETScWrappers::MPI::Vector>  near_null_space,
                                   const LinearSolverSettings                      &settings,
                                   const unsigned int                               block_size,
                                   PC                                              *kept_preconditioner)
  {
    Mat      A = matrix;
    MPI_Comm comm = matrix.get_mpi_communicator();
    KSP      ksp;
    PC       pc;
    check(KSPCreate(comm, &ksp), "KSPCreate");
    check(KSPSetOperators(ksp, A, A), "KSPSetOperators");
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    if (settings.method == SolverMethod::direct)
      {
        check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
        check(PCSetType(pc, PCLU), "PCSetType");
        check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
      }
    else
      {
        check(KSPSetType(ksp, KSPCG), "KSPSetType");
        configure_gamg(pc, matrix, near_null_space, block_size, "");
      }
    check(KSPSetTolerances(ksp, settings.relative_tolerance, 1e-300, PETSC_DEFAULT,
                           settings.max_iterations),
          "KSPSetTolerances");
    insert_petsc_options(settings.petsc_options);
    check(KSPSetFromOptions(ksp), "KSPSetFromOptions");
    Vec x = solution;
    check(KSPSolve(ksp, rhs, x), "KSPSolve");
    KSPConvergedReason reason;
    PetscInt           iterations;
    KSPGetConvergedReason(ksp, &reason);
    KSPGetIterationNumber(ksp, &iterations);
    PCType type = nullptr;
    PCGetType(pc, &type);
    // Only GAMG is kept (PETSc options may have made it another, e.g. an unsymmetric SOR).
    if (kept_preconditioner && reason >= 0 && type != nullptr && std::string(type) == PCGAMG)
      {
        check(PetscObjectReference(reinterpret_cast<PetscObject>(pc)), "PetscObjectReference");
        *kept_preconditioner = pc;
      }
    KSPDestroy(&ksp);
    if (reason < 0)
      throw std::runtime_error("linear solver (" + to_string(settings.method) + ") did not converge: PETSc "
                               "reason " + std::to_string(reason) + " after " +
                               std::to_string(iterations) + " iterations; try 'Linear "
                               "solver/Method = direct' or more iterations");
    return iterations;
  }
  void insert_petsc_options(const std::string &petsc_options)
  {
    if (!petsc_options.empty())
      check(PetscOptionsInsertString(nullptr, petsc_options.c_str()),
            "PetscOptionsInsertString (Linear solver/PETSc options)");
  }

  unsigned int count_negative_eigenvalues(dealii::PETScWrappers::MPI::SparseMatrix &matrix)
  {
    DirectFactorization factorization;
    factorization.factor(matrix, true);
    return factorization.negative_eigenvalues();
  }
} // namespace compliant
