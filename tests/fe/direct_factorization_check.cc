// DirectFactorization (MUMPS through PETSc): x = A^-1 b and its transposed solve x = A^-T b from
// the same factors, on an unsymmetric matrix (the dual of an unsymmetric Newton tangent needs the
// transpose). Each answer is checked by its residual; the two differ, so a solve that ignored the
// transpose fails.
#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "linear_algebra/direct_factorization.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace dealii;

namespace
{
  // A tridiagonal, diagonally dominant and unsymmetric n x n matrix: 4 on the diagonal, -1 below, 2 - i/n above.
  void fill(PETScWrappers::MPI::SparseMatrix &a, const IndexSet &owned, const unsigned int n)
  {
    DynamicSparsityPattern pattern(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = (i > 0 ? i - 1 : 0); j <= std::min(i + 1, n - 1); ++j)
        pattern.add(i, j);
    a.reinit(owned, owned, pattern, MPI_COMM_WORLD);
    for (const auto i : owned)
      {
        a.set(i, i, 4.);
        if (i > 0)
          a.set(i, i - 1, -1.);
        if (i + 1 < n)
          a.set(i, i + 1, 2. - double(i) / n);
      }
    a.compress(VectorOperation::insert);
  }

  // Rows cut in blocks over the ranks (the ctest runs 1 and 2).
  IndexSet owned_rows(const unsigned int n)
  {
    const unsigned int rank = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int size = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    IndexSet           owned(n);
    owned.add_range(rank * n / size, (rank + 1) * n / size);
    return owned;
  }

  // fill() made symmetric: -1 above the diagonal too.
  void make_symmetric(PETScWrappers::MPI::SparseMatrix &a, const IndexSet &owned, const unsigned int n)
  {
    for (const auto i : owned)
      if (i + 1 < n)
        a.set(i, i + 1, -1.);
    a.compress(VectorOperation::insert);
  }

  // New values on the same pattern, as a Newton iteration's tangent has.
  void set_diagonal(PETScWrappers::MPI::SparseMatrix &a, const IndexSet &owned, const double diagonal)
  {
    for (const auto i : owned)
      a.set(i, i, diagonal);
    a.compress(VectorOperation::insert);
  }
} // namespace

TEST(DirectFactorization, SolvesWithTheMatrixAndItsTranspose)
{
  const unsigned int n     = 40;
  const IndexSet     owned = owned_rows(n);
  PETScWrappers::MPI::SparseMatrix a;
  fill(a, owned, n);
  PETScWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b), y(b), residual(b);
  for (const auto i : owned)
    b(i) = std::sin(1. + i);
  b.compress(VectorOperation::insert);

  compliant::DirectFactorization factor;
  factor.factor(a, false);
  factor.solve(x, b);
  factor.solve_transpose(y, b);

  a.vmult(residual, x);
  residual -= b;
  EXPECT_LT(residual.linfty_norm(), 1e-13 * b.linfty_norm());
  a.Tvmult(residual, y);
  residual -= b;
  EXPECT_LT(residual.linfty_norm(), 1e-13 * b.linfty_norm());
  residual = x;
  residual -= y;
  EXPECT_GT(residual.linfty_norm(), 1e-3 * x.linfty_norm()); // the transpose is a different system
}

// A second factor() on the same matrix object keeps MUMPS's analysis and redoes only the numbers
// (a Newton iteration's new tangent): the solve must be that of the new values, LU or LDL^T. A
// factor kept stale would leave a residual of the order of the change (here 2 on the diagonal).
TEST(DirectFactorization, RefactorsNewValuesOnTheKeptPattern)
{
  const unsigned int n     = 40;
  const IndexSet     owned = owned_rows(n);
  for (const bool symmetric : {false, true})
    {
      PETScWrappers::MPI::SparseMatrix a;
      fill(a, owned, n);
      if (symmetric)
        make_symmetric(a, owned, n);
      PETScWrappers::MPI::Vector b(owned, MPI_COMM_WORLD), x(b), residual(b);
      for (const auto i : owned)
        b(i) = std::sin(1. + i);
      b.compress(VectorOperation::insert);

      compliant::DirectFactorization factor;
      for (const double diagonal : {4., 6., 3.})
        {
          set_diagonal(a, owned, diagonal);
          factor.factor(a, symmetric, false, false);
          factor.solve(x, b);
          a.vmult(residual, x);
          residual -= b;
          EXPECT_LT(residual.linfty_norm(), 1e-13 * b.linfty_norm()) << (symmetric ? "LDL^T" : "LU")
                                                                     << ", diagonal " << diagonal;
        }
    }
}

// The inertia after a refactorization is that of the new values: diagonal d - 2 cos(k pi / (n+1))
// for the symmetric tridiagonal (d, -1, -1) has as many negative eigenvalues as k with
// 2 cos(k pi / (n + 1)) > d.
TEST(DirectFactorization, InertiaFollowsTheNewValues)
{
  const unsigned int n     = 40;
  const IndexSet     owned = owned_rows(n);
  PETScWrappers::MPI::SparseMatrix a;
  fill(a, owned, n);
  make_symmetric(a, owned, n);
  compliant::DirectFactorization factor;
  for (const double d : {4., 1.5, -0.3})
    {
      set_diagonal(a, owned, d);
      factor.factor(a, true);
      unsigned int expected = 0;
      for (unsigned int k = 1; k <= n; ++k)
        expected += 2 * std::cos(k * M_PI / (n + 1)) > d;
      EXPECT_EQ(factor.negative_eigenvalues(), expected) << "diagonal " << d;
    }
}
