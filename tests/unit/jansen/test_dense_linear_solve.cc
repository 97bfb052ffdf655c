#include <mechanisms/jansen/dense_linear_solve.h>

#include <gtest/gtest.h>

using namespace compliant::jansen;

// A system built from a chosen solution: needs pivoting (zero leading entry).
TEST(DenseLinearSolve, RecoversAChosenSolution)
{
  const DenseMatrix<4> a = {{{0., 2., -1., 3.},
                             {4., 1., 0.5, -2.},
                             {-1., 3., 7., 1.},
                             {2., -5., 1., 6.}}};
  const DenseVector<4> x = {1.5, -2., 0.25, 3.};
  DenseVector<4>       b{};
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      b[i] += a[i][j] * x[j];
  const auto solution = solve_dense<4>(a, b);
  ASSERT_TRUE(solution);
  for (std::size_t i = 0; i < 4; ++i)
    EXPECT_NEAR((*solution)[i], x[i], 1e-13);
}

TEST(DenseLinearSolve, ReportsASingularMatrix)
{
  const DenseMatrix<3> a = {{{1., 2., 3.}, {2., 4., 6.}, {0., 1., 1.}}}; // row 2 = 2 row 1
  EXPECT_FALSE((solve_dense<3>(a, {1., 2., 3.})));
}
