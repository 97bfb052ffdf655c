#include "fast_solver/long_edge_coarse_solver.h"
#include "linear_algebra/petsc_check.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace compliant::fast_solver
{
  namespace
  {
    const PetscErrorCheck check("long-edge coarse solve");
  } // namespace

  template <int dim>
  LongEdgeCoarseSolver<dim>::LongEdgeCoarseSolver(const MatrixFreeOperatorBase<dim, double> &level_operator_in,
                                                  const dealii::MGSmootherBase<VectorType>  &smoother_in,
                                                  std::shared_ptr<const LongEdgeSpace>       space_in,
                                                  MPI_Comm                                   communicator_in)
    : level_operator(level_operator_in)
    , smoother(smoother_in)
    , space(std::move(space_in))
    , communicator(communicator_in)
  {
    // PETSc objects made before a failure are released here: the destructor does not run.
    try
      {
        const PetscInt n = space->n_owned_coarse, size = space->n_coarse;
        // The pattern of the owned rows, from the owned cells and the other ranks' cells at them.
        PetscInt first = 0;
        check(MatGetOwnershipRangeColumn(space->prolongation, &first, nullptr), "MatGetOwnershipRangeColumn");
        std::vector<std::vector<PetscInt>> rows(n);
        const auto add = [&](const std::vector<PetscInt> &columns) {
          for (const auto row : columns)
            if (row >= first && row < first + n)
              rows[row - first].insert(rows[row - first].end(), columns.begin(), columns.end());
        };
        for (const auto &cell : space->cells)
          add(cell.columns);
        for (const auto &columns : space->neighbour_columns)
          add(columns);
        std::vector<PetscInt> diagonal_block(n, 0), off_diagonal_block(n, 0);
        for (PetscInt i = 0; i < n; ++i)
          {
            auto &row = rows[i];
            std::sort(row.begin(), row.end());
            row.erase(std::unique(row.begin(), row.end()), row.end());
            for (const auto column : row)
              ++(column >= first && column < first + n ? diagonal_block[i] : off_diagonal_block[i]);
          }
        check(MatCreate(communicator, &matrix), "MatCreate");
        check(MatSetType(matrix, MATMPIAIJ), "MatSetType(mpiaij)");
        check(MatSetSizes(matrix, n, n, size, size), "MatSetSizes");
        check(MatMPIAIJSetPreallocation(matrix, 0, diagonal_block.data(), 0, off_diagonal_block.data()),
              "MatMPIAIJSetPreallocation");
        check(MatSetOption(matrix, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
        check(MatCreateVecs(matrix, &solution, &rhs), "MatCreateVecs");
        level_operator.initialize_dof_vector(residual);
        check(VecCreateMPIWithArray(communicator, 1, residual.locally_owned_size(), PETSC_DETERMINE, nullptr, &wrapped),
              "VecCreateMPIWithArray");

        PC pc;
        check(KSPCreate(communicator, &ksp), "KSPCreate");
        check(KSPSetType(ksp, KSPPREONLY), "KSPSetType(preonly)");
        check(KSPGetPC(ksp, &pc), "KSPGetPC");
        check(PCSetType(pc, PCCHOLESKY), "PCSetType(cholesky)");
        check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
        refactor();
      }
    catch (...)
      {
        release();
        throw;
      }
  }

  template <int dim>
  LongEdgeCoarseSolver<dim>::~LongEdgeCoarseSolver()
  {
    release();
  }

  template <int dim>
  void LongEdgeCoarseSolver<dim>::release()
  {
    KSPDestroy(&ksp);
    MatDestroy(&matrix);
    VecDestroy(&rhs);
    VecDestroy(&solution);
    VecDestroy(&wrapped);
  }

  template <int dim>
  void LongEdgeCoarseSolver<dim>::assemble()
  {
    PetscBool assembled = PETSC_FALSE;
    check(MatAssembled(matrix, &assembled), "MatAssembled");
    if (assembled)
      check(MatZeroEntries(matrix), "MatZeroEntries");
    level_operator.add_kernel_subspace_matrix(*space, matrix);
    check(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    check(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    check(MatSetOption(matrix, MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(symmetric)");
  }

  template <int dim>
  void LongEdgeCoarseSolver<dim>::refactor()
  {
    assemble();
    check(KSPSetOperators(ksp, matrix, matrix), "KSPSetOperators");
    check(KSPSetUp(ksp), "KSPSetUp (MUMPS factorization)");
  }

  template <int dim>
  void LongEdgeCoarseSolver<dim>::operator()(const unsigned int level, VectorType &dst, const VectorType &src) const
  {
    smoother.apply(level, dst, src);
    level_operator.vmult(residual, dst);
    residual.sadd(-1., 1., src);
    // The residual's own storage as a PETSc vector, given back however the solve ends.
    check(VecPlaceArray(wrapped, residual.begin()), "VecPlaceArray");
    const PetscErrorCode status = [&]() {
      PetscErrorCode ierr = MatMultTranspose(space->prolongation, wrapped, rhs);
      if (ierr == 0)
        ierr = KSPSolve(ksp, rhs, solution);
      if (ierr == 0)
        ierr = MatMult(space->prolongation, solution, wrapped);
      return ierr;
    }();
    check(VecResetArray(wrapped), "VecResetArray");
    check(status, "the coarse solve (P^T, MUMPS, P)");
    dst += residual;
    smoother.smooth(level, dst, src);
    ++n_solves;
  }

  template class LongEdgeCoarseSolver<2>;
  template class LongEdgeCoarseSolver<3>;
} // namespace compliant::fast_solver
