#include "fast_solver/long_edge_coarse_solver.h"

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

#include <stdexcept>
#include <string>
#include <vector>

namespace compliant::fast_solver
{
  namespace
  {
    void check(const PetscErrorCode ierr, const char *what)
    {
      if (ierr != 0)
        throw std::runtime_error(std::string("long-edge coarse solve: PETSc error in ") + what);
    }
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
    const PetscInt n = space->n_owned_coarse, size = space->n_coarse;
    // The pattern: every cell couples all the coarse DoFs it reaches; rows of other ranks go to them.
    PetscInt first = 0;
    check(MatGetOwnershipRangeColumn(space->prolongation, &first, nullptr), "MatGetOwnershipRangeColumn");
    dealii::IndexSet owned(size), relevant(size);
    owned.add_range(first, first + n);
    relevant.add_range(first, first + n);
    std::vector<dealii::types::global_dof_index> columns;
    for (const auto &cell : space->cells)
      for (const auto column : cell.columns)
        columns.push_back(column);
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    relevant.add_indices(columns.begin(), columns.end());
    dealii::DynamicSparsityPattern pattern(size, size, relevant);
    for (const auto &cell : space->cells)
      {
        columns.assign(cell.columns.begin(), cell.columns.end());
        std::sort(columns.begin(), columns.end());
        for (const auto row : columns)
          pattern.add_entries(row, columns.begin(), columns.end(), true);
      }
    dealii::SparsityTools::distribute_sparsity_pattern(pattern, owned, communicator, relevant);
    galerkin.reinit(owned, owned, pattern, communicator);
    matrix = galerkin;
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

  template <int dim>
  LongEdgeCoarseSolver<dim>::~LongEdgeCoarseSolver()
  {
    KSPDestroy(&ksp);
    VecDestroy(&rhs);
    VecDestroy(&solution);
    VecDestroy(&wrapped);
  }

  template <int dim>
  void LongEdgeCoarseSolver<dim>::assemble()
  {
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
    check(VecPlaceArray(wrapped, residual.begin()), "VecPlaceArray");
    check(MatMultTranspose(space->prolongation, wrapped, rhs), "MatMultTranspose");
    check(KSPSolve(ksp, rhs, solution), "KSPSolve");
    check(MatMult(space->prolongation, solution, wrapped), "MatMult");
    check(VecResetArray(wrapped), "VecResetArray");
    dst += residual;
    smoother.smooth(level, dst, src);
    ++n_solves;
  }

  template class LongEdgeCoarseSolver<2>;
  template class LongEdgeCoarseSolver<3>;
} // namespace compliant::fast_solver
