// Gaussian elimination with partial pivoting for the small dense systems of
// velocity and acceleration analysis (6 x 6 for the Jansen leg).
#pragma once

#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace compliant
{
  namespace jansen
  {
    template <std::size_t n>
    using DenseMatrix = std::array<std::array<double, n>, n>;

    template <std::size_t n>
    using DenseVector = std::array<double, n>;

    // Solves matrix * x = rhs. Returns nothing when a pivot falls below
    // relative_pivot_tolerance times the largest entry of the matrix: the
    // system is singular (a dead point of the mechanism).
    template <std::size_t n>
    std::optional<DenseVector<n>> solve_dense(DenseMatrix<n> matrix,
                                              DenseVector<n> rhs,
                                              const double   relative_pivot_tolerance = 1e-12)
    {
      double largest_entry = 0.;
      for (const auto &row : matrix)
        for (const double entry : row)
          largest_entry = std::max(largest_entry, std::abs(entry));
      const double pivot_floor = relative_pivot_tolerance * largest_entry;

      for (std::size_t column = 0; column < n; ++column)
        {
          std::size_t pivot_row = column;
          for (std::size_t row = column + 1; row < n; ++row)
            if (std::abs(matrix[row][column]) > std::abs(matrix[pivot_row][column]))
              pivot_row = row;
          if (!(std::abs(matrix[pivot_row][column]) > pivot_floor))
            return std::nullopt;
          std::swap(matrix[column], matrix[pivot_row]);
          std::swap(rhs[column], rhs[pivot_row]);

          for (std::size_t row = column + 1; row < n; ++row)
            {
              const double factor = matrix[row][column] / matrix[column][column];
              for (std::size_t k = column; k < n; ++k)
                matrix[row][k] -= factor * matrix[column][k];
              rhs[row] -= factor * rhs[column];
            }
        }

      DenseVector<n> solution{};
      for (std::size_t row = n; row-- > 0;)
        {
          double sum = rhs[row];
          for (std::size_t k = row + 1; k < n; ++k)
            sum -= matrix[row][k] * solution[k];
          solution[row] = sum / matrix[row][row];
        }
      return solution;
    }
  } // namespace jansen
} // namespace compliant
