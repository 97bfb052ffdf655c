#include "torsion.h"

#include "beams.h"
#include "input_checks.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace closed_forms
{
  using internal::require_finite;
  using internal::require_positive;

  namespace
  {
    // Sums over odd n of 1/n^s, (1 - 2^-s) zeta(s); zeta(5), zeta(7) from DLMF 25.6 / OEIS A013663,
    // A013665. Writing tanh = 1 - (1 - tanh) leaves an exponentially convergent remainder.
    constexpr double zeta_5 = 1.0369277551433699263;
    constexpr double zeta_7 = 1.0083492773819228268;
    constexpr double odd_sum_5 = (1.0 - 1.0 / 32.0) * zeta_5;
    constexpr double odd_sum_7 = (1.0 - 1.0 / 128.0) * zeta_7;

    // Terms below this fraction of the sum they correct are dropped.
    constexpr double series_tolerance = 1e-16;

    // 1 - tanh(x) without cancellation, x >= 0.
    double
    one_minus_tanh(const double x)
    {
      return 2.0 / (std::exp(2.0 * x) + 1.0);
    }

    // 1 / cosh(x)^2 without overflow, x >= 0.
    double
    sech_squared(const double x)
    {
      const double e = std::exp(-2.0 * x);
      return 4.0 * e / ((1.0 + e) * (1.0 + e));
    }

    std::pair<double, double>
    sorted_sides(const double a, const double b)
    {
      require_positive("a", a);
      require_positive("b", b);
      return {std::max(a, b), std::min(a, b)};
    }

    // Sum over odd n = 1, 3, ... of term(n) until a term drops below series_tolerance * scale.
    template <typename Term>
    double
    sum_over_odd(const Term &term, const double scale)
    {
      double sum = 0.0;
      for (unsigned int n = 1; n < 4000001; n += 2)
        {
          const double value = term(n);
          sum += value;
          if (std::abs(value) <= series_tolerance * scale)
            break;
        }
      return sum;
    }
  } // namespace

  double
  saint_venant_beta(const double a_in, const double b_in)
  {
    const auto [a, b] = sorted_sides(a_in, b_in);
    const double r = a / b;
    const double remainder =
      sum_over_odd([r](unsigned int n) { return one_minus_tanh(0.5 * n * M_PI * r) / std::pow(n, 5); },
                   odd_sum_5);
    return (1.0 - 192.0 / std::pow(M_PI, 5) / r * (odd_sum_5 - remainder)) / 3.0;
  }

  double
  saint_venant_stress_factor(const double a_in, const double b_in)
  {
    const auto [a, b] = sorted_sides(a_in, b_in);
    const double r = a / b;
    const double sum = sum_over_odd(
      [r](unsigned int n) { return 1.0 / (double(n) * n * std::cosh(0.5 * n * M_PI * r)); }, 1.0);
    return 1.0 - 8.0 / (M_PI * M_PI) * sum;
  }

  double
  saint_venant_alpha(const double a, const double b)
  {
    return saint_venant_beta(a, b) / saint_venant_stress_factor(a, b);
  }

  double
  torsion_constant(const double a_in, const double b_in)
  {
    const auto [a, b] = sorted_sides(a_in, b_in);
    return saint_venant_beta(a, b) * a * b * b * b;
  }

  double
  saint_venant_max_shear_stress(const double T, const double a_in, const double b_in)
  {
    require_finite("T", T);
    const auto [a, b] = sorted_sides(a_in, b_in);
    return T / (saint_venant_alpha(a, b) * a * b * b);
  }

  double
  saint_venant_torsion_stiffness(const double a, const double b, const double L, const double E,
                                 const double nu)
  {
    require_positive("L", L);
    return shear_modulus(E, nu) * torsion_constant(a, b) / L;
  }

  // Derivation (project's own, checked against a finite-difference solve in the unit tests):
  // omega solves Laplace's equation with d omega/dn = y n_x - x n_y on the boundary. With
  // omega = -x y + chi, chi is harmonic, odd in x and y, with d chi/dy = 0 on y = +-b/2 and
  // d chi/dx = 2 y on x = +-a/2, so chi = sum_{n odd} c_n sinh(k_n x) sin(k_n y), k_n = n pi / b,
  // c_n = 8 s_n / (b k_n^3 cosh(k_n a/2)), s_n = (-1)^((n-1)/2) (Fourier sine series of 2y).
  double
  warping_function(const double a_in, const double b_in, const double x_in, const double y_in)
  {
    require_positive("a", a_in);
    require_positive("b", b_in);
    require_finite("x", x_in);
    require_finite("y", y_in);
    // A bar with a < b is the sorted bar turned by 90 degrees; omega is invariant under that rotation.
    const bool turned = a_in < b_in;
    const double a = turned ? b_in : a_in;
    const double b = turned ? a_in : b_in;
    const double x = turned ? y_in : x_in;
    const double y = turned ? -x_in : y_in;
    const double slack = 1e-12 * a;
    if (std::abs(x) > 0.5 * a + slack || std::abs(y) > 0.5 * b + slack)
      throw std::invalid_argument("closed_forms: point (x, y) = (" + internal::format_number(x_in) +
                                  ", " + internal::format_number(y_in) +
                                  ") lies outside the rectangle");
    const double abs_x = std::min(std::abs(x), 0.5 * a);
    const double scale = 0.25 * a * b;
    double chi = 0.0;
    // Terms decay like exp(-k_n (a/2 - |x|)) / n^3: algebraically on the short sides, so cap n.
    for (unsigned int n = 1; n < 200001; n += 2)
      {
        const double k = n * M_PI / b;
        const double s = ((n - 1) / 2) % 2 == 0 ? 1.0 : -1.0;
        // sinh(k |x|) / cosh(k a/2) without overflow.
        const double ratio = (std::exp(k * (abs_x - 0.5 * a)) - std::exp(-k * (abs_x + 0.5 * a))) /
                             (1.0 + std::exp(-k * a));
        const double term = 8.0 * s / (b * k * k * k) * ratio * std::sin(k * y);
        chi += term;
        if (8.0 / (b * k * k * k) * std::exp(k * (abs_x - 0.5 * a)) < series_tolerance * scale)
          break;
      }
    return -x * y + (x < 0.0 ? -chi : chi);
  }

  // Gamma = int omega^2 dA with the series above, integrated term by term (sin(k_n y) are orthogonal
  // on [-b/2, b/2]):
  //   Gamma = a^3 b^3/144 + sum_{n odd} 32/(b k_n^6) [3 tanh(k_n a/2)/k_n - a (1 + sech^2(k_n a/2)/2)]
  // and with sum_{n odd} 1/k_n^6 = b^6/960:
  //   Gamma = a^3 b^3/144 - a b^5/30 + (96 b^6/pi^7) sum tanh(.)/n^7 - (16 a b^5/pi^6) sum sech^2(.)/n^6.
  double
  warping_constant(const double a_in, const double b_in)
  {
    const auto [a, b] = sorted_sides(a_in, b_in);
    const double r = a / b;
    const double tanh_remainder =
      sum_over_odd([r](unsigned int n) { return one_minus_tanh(0.5 * n * M_PI * r) / std::pow(n, 7); },
                   odd_sum_7);
    const double sech_sum =
      sum_over_odd([r](unsigned int n) { return sech_squared(0.5 * n * M_PI * r) / std::pow(n, 6); },
                   1.0);
    const double per_b6 = r * r * r / 144.0 - r / 30.0 +
                          96.0 / std::pow(M_PI, 7) * (odd_sum_7 - tanh_remainder) -
                          16.0 * r / std::pow(M_PI, 6) * sech_sum;
    return per_b6 * std::pow(b, 6);
  }

  // Vlasov torsion, T = G J phi' - E Gamma phi''', phi = phi' = 0 at s = 0 and phi' = 0 at s = L:
  // phi' = (T/GJ)[1 - cosh(lambda (s - L/2)) / cosh(lambda L/2)], integrated over L.
  double
  vlasov_torsion_stiffness(const double a, const double b, const double L, const double E,
                           const double nu)
  {
    require_positive("L", L);
    const double GJ = shear_modulus(E, nu) * torsion_constant(a, b);
    const double lambda = std::sqrt(GJ / (E * warping_constant(a, b)));
    const double x = 0.5 * lambda * L;
    // 1 - tanh(x)/x; the Taylor series avoids cancellation for small x (short bars).
    double restraint_factor;
    if (x < 0.02)
      {
        const double x2 = x * x;
        restraint_factor =
          x2 * (1.0 / 3.0 - x2 * (2.0 / 15.0 - x2 * (17.0 / 315.0 - x2 * 62.0 / 2835.0)));
      }
    else
      restraint_factor = 1.0 - std::tanh(x) / x;
    return GJ / (L * restraint_factor);
  }
} // namespace closed_forms
