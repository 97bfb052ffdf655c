#include "beams.h"

#include "torsion.h"

#include "input_checks.h"
#include "root_finding.h"

#include <cmath>
#include <stdexcept>

namespace closed_forms
{
  using internal::require_finite;
  using internal::require_poisson_ratio;
  using internal::require_positive;

  double
  second_moment_of_area(const double b, const double h)
  {
    require_positive("b", b);
    require_positive("h", h);
    return b * h * h * h / 12.0;
  }

  double
  section_area(const double b, const double h)
  {
    require_positive("b", b);
    require_positive("h", h);
    return b * h;
  }

  double
  shear_modulus(const double E, const double nu)
  {
    require_positive("E", E);
    require_poisson_ratio("nu", nu);
    return E / (2.0 * (1.0 + nu));
  }

  // Gere and Timoshenko, Mechanics of Materials, cantilever with end load.
  double
  euler_bernoulli_cantilever_deflection(const double P, const double L, const double E, const double b,
                                        const double h)
  {
    require_finite("P", P);
    require_positive("L", L);
    require_positive("E", E);
    return P * L * L * L / (3.0 * E * second_moment_of_area(b, h));
  }

  // Timoshenko and Gere, Mechanics of Materials: bending plus shear deflection P L / (kappa G A).
  double
  timoshenko_cantilever_deflection(const double P, const double L, const double E, const double nu,
                                   const double b, const double h, const double kappa)
  {
    require_positive("kappa", kappa);
    const double shear = P * L / (kappa * shear_modulus(E, nu) * section_area(b, h));
    return euler_bernoulli_cantilever_deflection(P, L, E, b, h) + shear;
  }

  // Timoshenko and Goodier sec. 21, in the form of Augarde and Deeks 2008, eq. (1)-(2) at (L, 0).
  double
  timoshenko_goodier_cantilever_deflection(const double P, const double L, const double E,
                                           const double nu, const double b, const double h)
  {
    const double EI = E * second_moment_of_area(b, h);
    return euler_bernoulli_cantilever_deflection(P, L, E, b, h) +
           (4.0 + 5.0 * nu) * P * h * h * L / (24.0 * EI);
  }

  double
  euler_bernoulli_guided_stiffness(const double L, const double E, const double b, const double h)
  {
    require_positive("L", L);
    require_positive("E", E);
    return 12.0 * E * second_moment_of_area(b, h) / (L * L * L);
  }

  // Two Timoshenko cantilevers of length L/2 joined at the inflection point.
  double
  timoshenko_guided_stiffness(const double L, const double E, const double nu, const double b,
                              const double h, const double kappa)
  {
    require_positive("L", L);
    require_positive("kappa", kappa);
    const double EI = E * second_moment_of_area(b, h);
    const double kGA = kappa * shear_modulus(E, nu) * section_area(b, h);
    const double Phi = 12.0 * EI / (kGA * L * L);
    return 12.0 * EI / (L * L * L * (1.0 + Phi));
  }

  double
  euler_column_load(const double L, const double E, const double b, const double h, const double K)
  {
    require_positive("L", L);
    require_positive("K", K);
    return M_PI * M_PI * E * second_moment_of_area(b, h) / (K * K * L * L);
  }

  double
  engesser_column_load(const double L, const double E, const double nu, const double b, const double h,
                       const double K, const double kappa)
  {
    require_positive("kappa", kappa);
    const double euler = euler_column_load(L, E, b, h, K);
    return euler / (1.0 + euler / (kappa * shear_modulus(E, nu) * section_area(b, h)));
  }

  double
  beam_column_end_moment_stiffness(const double L, const double E, const double b, const double h,
                                   const double P)
  {
    require_positive("L", L);
    require_positive("E", E);
    const double EI = E * second_moment_of_area(b, h);
    const double kL = std::sqrt(std::abs(P) / EI) * L;
    if (kL < 1e-6) // the series 1 - (kL)^2/3 (compression) or 1 + (kL)^2/3 (tension)
      return EI / L * (1.0 - (P > 0 ? 1.0 : -1.0) * kL * kL / 3.0);
    return EI / L * (P > 0 ? kL / std::tan(kL) : kL / std::tanh(kL));
  }

  double
  guided_beam_column_stiffness(const double L, const double E, const double b, const double h, const double P)
  {
    require_positive("L", L);
    require_positive("E", E);
    const double EI    = E * second_moment_of_area(b, h);
    const double q     = std::sqrt(std::abs(P) / EI) * L;
    const double scale = EI / (L * L * L);
    if (q < 1e-3) // 12 (1 -+ q^2 / 10): the differences below lose digits
      return scale * 12.0 * (1.0 - (P > 0 ? 1.0 : -1.0) * q * q / 10.0);
    if (P > 0)
      return scale * q * q * q * std::sin(q) / (2 * (1 - std::cos(q)) - q * std::sin(q));
    return scale * q * q * q * std::sinh(q) / (q * std::sinh(q) - 2 * (std::cosh(q) - 1));
  }

  double
  bcm_guided_stiffness(const double L, const double E, const double b, const double h, const double P)
  {
    require_positive("L", L);
    require_positive("E", E);
    const double EI = E * second_moment_of_area(b, h);
    const double p  = -P * L * L / EI;
    return EI / (L * L * L) * (12.0 + 1.2 * p - p * p / 700.0);
  }

  // 1 + cos x cosh x = 0 is rewritten as cos x + 1/cosh x = 0 so that cosh never overflows. On
  // [(n-1) pi, n pi] cos x changes sign and 1/cosh x < 1 is too small to remove that change, so each
  // interval holds the n-th root.
  double
  cantilever_frequency_root(const unsigned int n)
  {
    if (n == 0)
      throw std::invalid_argument("closed_forms: parameter 'n' (mode number) must be >= 1, got 0");
    const auto characteristic = [](const double x) { return std::cos(x) + 1.0 / std::cosh(x); };
    return internal::find_root_by_bisection(characteristic, (n - 1) * M_PI, n * M_PI);
  }

  // Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1 (clamped-free).
  double
  euler_bernoulli_cantilever_angular_frequency(const unsigned int n, const double L, const double E,
                                               const double rho, const double b, const double h)
  {
    require_positive("L", L);
    require_positive("E", E);
    require_positive("rho", rho);
    const double beta_L = cantilever_frequency_root(n);
    const double EI = E * second_moment_of_area(b, h);
    const double mass_per_length = rho * section_area(b, h);
    return beta_L * beta_L * std::sqrt(EI / (mass_per_length * std::pow(L, 4)));
  }

  double
  euler_bernoulli_cantilever_frequency(const unsigned int n, const double L, const double E,
                                       const double rho, const double b, const double h)
  {
    return euler_bernoulli_cantilever_angular_frequency(n, L, E, rho, b, h) / (2.0 * M_PI);
  }

  double lateral_torsional_buckling_moment(const double L, const double E, const double nu, const double h,
                                           const double b)
  {
    internal::require_positive("L", L);
    internal::require_positive("E", E);
    internal::require_positive("h", h);
    internal::require_positive("b", b);
    if (!(nu > -1 && nu < 0.5))
      throw std::invalid_argument("closed_forms: argument 'nu' must lie in (-1, 0.5), got " + internal::format_number(nu));
    const double I_y = h * b * b * b / 12;
    const double G   = E / (2 * (1 + nu));
    const double J   = torsion_constant(h, b);
    return M_PI / L * std::sqrt(E * I_y * G * J);
  }
} // namespace closed_forms
