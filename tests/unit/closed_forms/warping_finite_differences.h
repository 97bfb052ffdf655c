// Independent check of the warping series: a finite-volume solve of the Saint-Venant warping problem
//   Laplace(omega) = 0 in the rectangle, d omega/dn = y n_x - x n_y on its boundary,
// on a cell-centred grid, by conjugate gradients (the Neumann problem is singular; the mean is
// projected out). Second-order accurate, so two grids give a Richardson extrapolation.
#ifndef CLOSED_FORMS_TESTS_WARPING_FINITE_DIFFERENCES_H
#define CLOSED_FORMS_TESTS_WARPING_FINITE_DIFFERENCES_H

#include <cmath>
#include <vector>

namespace closed_forms_tests
{
  struct WarpingSolution
  {
    double a, b;
    unsigned int nx, ny;
    std::vector<double> omega;  // cell values, index i + nx j
    double warping_constant;    // sum omega^2 dA
    double torsion_constant;    // I_p - boundary integral of omega g, g = d omega/dn
    double x(unsigned int i) const { return -0.5 * a + (i + 0.5) * a / nx; }
    double y(unsigned int j) const { return -0.5 * b + (j + 0.5) * b / ny; }
  };

  inline WarpingSolution
  solve_warping_by_finite_volumes(const double a, const double b, const unsigned int nx,
                                  const unsigned int ny)
  {
    const double hx = a / nx, hy = b / ny;
    const std::size_t size = std::size_t(nx) * ny;
    const auto index = [nx](unsigned int i, unsigned int j) { return i + std::size_t(nx) * j; };

    // Right-hand side: boundary flux g = y n_x - x n_y integrated over each boundary face
    // (g is linear along a face, so the midpoint rule is exact).
    std::vector<double> rhs(size, 0.0);
    for (unsigned int j = 0; j < ny; ++j)
      {
        const double yc = -0.5 * b + (j + 0.5) * hy;
        rhs[index(0, j)] += -yc * hy;       // x = -a/2, n = (-1, 0)
        rhs[index(nx - 1, j)] += yc * hy;   // x = +a/2, n = (+1, 0)
      }
    for (unsigned int i = 0; i < nx; ++i)
      {
        const double xc = -0.5 * a + (i + 0.5) * hx;
        rhs[index(i, 0)] += xc * hx;        // y = -b/2, n = (0, -1)
        rhs[index(i, ny - 1)] += -xc * hx;  // y = +b/2, n = (0, +1)
      }

    // Operator: sum over interior faces of (omega_P - omega_neighbour) * face length / distance.
    const double wx = hy / hx, wy = hx / hy;
    const auto apply = [&](const std::vector<double> &u, std::vector<double> &result) {
      for (unsigned int j = 0; j < ny; ++j)
        for (unsigned int i = 0; i < nx; ++i)
          {
            const double up = u[index(i, j)];
            double sum = 0.0;
            if (i > 0)
              sum += wx * (up - u[index(i - 1, j)]);
            if (i + 1 < nx)
              sum += wx * (up - u[index(i + 1, j)]);
            if (j > 0)
              sum += wy * (up - u[index(i, j - 1)]);
            if (j + 1 < ny)
              sum += wy * (up - u[index(i, j + 1)]);
            result[index(i, j)] = sum;
          }
    };
    const auto dot = [](const std::vector<double> &u, const std::vector<double> &v) {
      double sum = 0.0;
      for (std::size_t k = 0; k < u.size(); ++k)
        sum += u[k] * v[k];
      return sum;
    };

    std::vector<double> omega(size, 0.0), residual = rhs, direction = rhs, product(size);
    double residual_norm2 = dot(residual, residual);
    const double stop = 1e-26 * residual_norm2;
    for (unsigned int iteration = 0; iteration < 20 * size && residual_norm2 > stop; ++iteration)
      {
        apply(direction, product);
        const double step = residual_norm2 / dot(direction, product);
        for (std::size_t k = 0; k < size; ++k)
          {
            omega[k] += step * direction[k];
            residual[k] -= step * product[k];
          }
        const double new_norm2 = dot(residual, residual);
        for (std::size_t k = 0; k < size; ++k)
          direction[k] = residual[k] + new_norm2 / residual_norm2 * direction[k];
        residual_norm2 = new_norm2;
      }
    double mean = 0.0;
    for (const double value : omega)
      mean += value / size;
    for (double &value : omega)
      value -= mean;

    WarpingSolution solution{a, b, nx, ny, omega, 0.0, 0.0};
    for (const double value : omega)
      solution.warping_constant += value * value * hx * hy;
    // J = I_p + int (x omega_y - y omega_x) dA = I_p - boundary integral of omega g (Green), with
    // omega carried from the cell centre to the face midpoint by omega + (h/2) g.
    double boundary_integral = 0.0;
    for (unsigned int j = 0; j < ny; ++j)
      {
        const double g = solution.y(j);  // on x = +a/2; the opposite face has -g and -omega
        boundary_integral += (omega[index(nx - 1, j)] + 0.5 * hx * g) * g * hy;
        boundary_integral += (omega[index(0, j)] - 0.5 * hx * g) * (-g) * hy;
      }
    for (unsigned int i = 0; i < nx; ++i)
      {
        const double g = -solution.x(i);  // on y = +b/2
        boundary_integral += (omega[index(i, ny - 1)] + 0.5 * hy * g) * g * hx;
        boundary_integral += (omega[index(i, 0)] - 0.5 * hy * g) * (-g) * hx;
      }
    const double polar_moment = a * b * (a * a + b * b) / 12.0;
    solution.torsion_constant = polar_moment - boundary_integral;
    return solution;
  }
} // namespace closed_forms_tests

#endif
