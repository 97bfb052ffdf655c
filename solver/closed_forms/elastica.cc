#include "elastica.h"

#include "input_checks.h"
#include "root_finding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace closed_forms
{
  using internal::require_finite;

  namespace
  {
    // Carlson's symmetric integrals R_F and R_D by duplication (Carlson, Numer. Algorithms 10:13,
    // 1995; Press et al., Numerical Recipes 3rd ed. sec. 6.12). The error scales as tolerance^6, so
    // these tolerances give double precision.
    double
    carlson_rf(double x, double y, double z)
    {
      constexpr double tolerance = 0.0025;
      double dx, dy, dz, mean;
      do
        {
          const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
          const double lambda = sx * (sy + sz) + sy * sz;
          x = 0.25 * (x + lambda);
          y = 0.25 * (y + lambda);
          z = 0.25 * (z + lambda);
          mean = (x + y + z) / 3.0;
          dx = (mean - x) / mean;
          dy = (mean - y) / mean;
          dz = (mean - z) / mean;
        }
      while (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) > tolerance);
      const double e2 = dx * dy - dz * dz;
      const double e3 = dx * dy * dz;
      return (1.0 + (e2 / 24.0 - 0.1 - 3.0 * e3 / 44.0) * e2 + e3 / 14.0) / std::sqrt(mean);
    }

    double
    carlson_rd(double x, double y, double z)
    {
      constexpr double tolerance = 0.0015;
      double sum = 0.0, factor = 1.0, dx, dy, dz, mean;
      do
        {
          const double sx = std::sqrt(x), sy = std::sqrt(y), sz = std::sqrt(z);
          const double lambda = sx * (sy + sz) + sy * sz;
          sum += factor / (sz * (z + lambda));
          factor *= 0.25;
          x = 0.25 * (x + lambda);
          y = 0.25 * (y + lambda);
          z = 0.25 * (z + lambda);
          mean = 0.2 * (x + y + 3.0 * z);
          dx = (mean - x) / mean;
          dy = (mean - y) / mean;
          dz = (mean - z) / mean;
        }
      while (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) > tolerance);
      const double ea = dx * dy, eb = dz * dz, ec = ea - eb, ed = ea - 6.0 * eb, ee = ed + ec + ec;
      const double c1 = 3.0 / 14.0, c2 = 1.0 / 6.0, c3 = 9.0 / 22.0, c4 = 3.0 / 26.0,
                   c5 = 0.25 * c3, c6 = 1.5 * c4;
      return 3.0 * sum +
             factor *
               (1.0 + ed * (-c1 + c5 * ed - c6 * dz * ee) +
                dz * (c2 * ee + dz * (-c3 * ec + dz * c4 * ea))) /
               (mean * std::sqrt(mean));
    }

    constexpr double max_load_parameter = 1e5;
  } // namespace

  // DLMF 19.25.5 and 19.25.9: F = s R_F(c^2, 1 - m s^2, 1), E = F - (m/3) s^3 R_D(c^2, 1 - m s^2, 1).
  double
  elliptic_f(const double phi, const double m)
  {
    if (!(phi >= 0.0 && phi <= 0.5 * M_PI) || !(m <= 1.0))
      throw std::invalid_argument("closed_forms: elliptic_f needs 0 <= phi <= pi/2 and m <= 1");
    const double s = std::sin(phi), c = std::cos(phi);
    return s * carlson_rf(c * c, 1.0 - m * s * s, 1.0);
  }

  double
  elliptic_e(const double phi, const double m)
  {
    if (!(phi >= 0.0 && phi <= 0.5 * M_PI) || !(m <= 1.0))
      throw std::invalid_argument("closed_forms: elliptic_e needs 0 <= phi <= pi/2 and m <= 1");
    const double s = std::sin(phi), c = std::cos(phi), delta2 = 1.0 - m * s * s;
    return s * carlson_rf(c * c, delta2, 1.0) - m * s * s * s / 3.0 * carlson_rd(c * c, delta2, 1.0);
  }

  // Circular arc of curvature t / L (Howell 2001, sec. 5.4).
  CantileverTip
  end_moment_elastica(const double t)
  {
    require_finite("t", t);
    const double abs_t = std::abs(t);
    if (abs_t == 0.0)
      return {0.0, 0.0, 0.0};
    // 1 - cos t = 2 sin^2(t/2) has no cancellation.
    const double half_sin = std::sin(0.5 * abs_t);
    const double deflection = 2.0 * half_sin * half_sin / abs_t;
    double shortening;
    if (abs_t < 0.1)
      {
        // 1 - sin t / t by its Taylor series (cancellation otherwise); next term t^10/39916800.
        const double t2 = abs_t * abs_t;
        shortening = t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0)));
      }
    else
      shortening = 1.0 - std::sin(abs_t) / abs_t;
    return {t, std::copysign(deflection, t), shortening};
  }

  // Elastica EI theta'' = -P cos theta, theta(0) = 0, theta'(L) = 0. Its first integral
  // (L theta')^2 = 2 alpha (sin theta_0 - sin theta), theta_0 the tip rotation, with
  // 1 + sin theta = 2 m sin^2 phi, m = (1 + sin theta_0)/2, gives (Bisshopp and Drucker 1945)
  //   sqrt(alpha) = K(m) - F(phi_1, m),                 sin^2 phi_1 = 1 / (2 m),
  //   v / L = 1 - (2 / sqrt(alpha)) [E(m) - E(phi_1, m)],
  //   x_tip / L = sqrt(2 sin theta_0 / alpha)          (moment balance at the clamp).
  // The differences are formed without cancellation by the addition theorem (Byrd and Friedman
  // 116.01; DLMF 19.11): with tan phi_1 tan psi = 1/sqrt(1 - m), K - F(phi_1) = F(psi) and
  // E - E(phi_1) = E(psi) - m sin phi_1 sin psi, where sin^2 psi = 2 sigma/(1 + sigma),
  // 1 - m sin^2 psi = 1 - sigma, sigma = sin theta_0.
  // The unknown is t = ln tan(theta_0/2) < 0: it resolves both theta_0 -> 0 (t -> -infinity) and
  // theta_0 -> 90 deg (t -> 0, where 1 - sin theta_0 would underflow a plain angle).
  CantileverTip
  tip_load_elastica(const double alpha_in)
  {
    require_finite("alpha", alpha_in);
    const double alpha = std::abs(alpha_in);
    if (alpha > max_load_parameter)
      throw std::invalid_argument("closed_forms: load parameter alpha = P L^2/(E I) must satisfy "
                                  "|alpha| <= 1e5, got " + internal::format_number(alpha_in));
    // Relative nonlinear corrections are O(alpha^2): linear theory is exact to rounding here.
    if (alpha < 1e-20)
      return {0.5 * alpha_in, alpha_in / 3.0, alpha * alpha / 15.0};

    struct Parts
    {
      double sigma;    // sin theta_0
      double q;        // (1 - sigma) / 2, accurate when tiny
      double sin_psi;
      double rf, rd;   // R_F, R_D at (cos^2 psi, 1 - sigma, 1)
    };
    const auto parts = [](const double t) {
      Parts p;
      p.sigma = 1.0 / std::cosh(t);
      const double half_complement = std::atan(std::tanh(-0.5 * t));  // (90 deg - theta_0)/2
      p.q = std::sin(half_complement) * std::sin(half_complement);
      p.sin_psi = std::sqrt(2.0 * p.sigma / (1.0 + p.sigma));
      const double cos2_psi = 2.0 * p.q / (1.0 + p.sigma);
      p.rf = carlson_rf(cos2_psi, 2.0 * p.q, 1.0);
      p.rd = carlson_rd(cos2_psi, 2.0 * p.q, 1.0);
      return p;
    };
    const double root_alpha = std::sqrt(alpha);
    // Length integral F(psi) minus sqrt(alpha); increases with t.
    const auto residual = [&](const double t) {
      const Parts p = parts(t);
      return p.sin_psi * p.rf - root_alpha;
    };
    // t = -50: theta_0 ~ 4e-22, F(psi) ~ 3e-11 < sqrt(1e-20). t = -1e-150: q ~ t^2/4 ~ 2.5e-301 is
    // still a normal double and F(psi) ~ ln(4 / sqrt(q)) - ln(1 + sqrt 2) ~ 346 > sqrt(1e5).
    double t;
    if (residual(-1.0) >= 0.0)
      t = internal::find_root_by_bisection(residual, -50.0, -1.0);
    else
      {
        // Large loads: t in (-1, -1e-150), searched on a logarithmic scale of -t.
        const double log_minus_t = internal::find_root_by_bisection(
          [&](const double s) { return residual(-std::exp(s)); }, std::log(1e-150), 0.0);
        t = -std::exp(log_minus_t);
      }
    const Parts p = parts(t);
    const double m = 1.0 - p.q;
    const double sin_phi1 = std::sqrt(0.5 / m);
    const double e_psi = p.sin_psi * p.rf - m * p.sin_psi * p.sin_psi * p.sin_psi / 3.0 * p.rd;

    const double rotation = 2.0 * std::atan(std::exp(t));
    const double deflection = 1.0 - 2.0 / root_alpha * (e_psi - m * sin_phi1 * p.sin_psi);
    const double shortening = 1.0 - std::sqrt(2.0 * p.sigma / alpha);
    return {std::copysign(rotation, alpha_in), std::copysign(deflection, alpha_in), shortening};
  }
} // namespace closed_forms
