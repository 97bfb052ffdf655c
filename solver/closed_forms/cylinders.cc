#include "cylinders.h"

#include "input_checks.h"

#include <stdexcept>

namespace closed_forms
{
  using internal::format_number;
  using internal::require_positive;

  namespace
  {
    void check_radii(const double a, const double b, const double r)
    {
      require_positive("a", a);
      if (!(b > a))
        throw std::invalid_argument("closed_forms: the outer radius 'b' must exceed the inner "
                                    "radius 'a', got a = " + format_number(a) + ", b = " + format_number(b));
      if (!(r >= a && r <= b))
        throw std::invalid_argument("closed_forms: radius 'r' must lie in the wall, a <= r <= b, got " +
                                    format_number(r));
    }

    double coefficient_A(const double a, const double b, const double p_i, const double p_o)
    {
      return (p_i * a * a - p_o * b * b) / (b * b - a * a);
    }

    double coefficient_B(const double a, const double b, const double p_i, const double p_o)
    {
      return (p_i - p_o) * a * a * b * b / (b * b - a * a);
    }
  } // namespace

  double lame_radial_displacement(const double a, const double b, const double p_i, const double p_o,
                                  const double E, const double nu, const double r,
                                  const bool plane_strain)
  {
    check_radii(a, b, r);
    require_positive("E", E);
    if (!(nu > -1 && nu < 0.5))
      throw std::invalid_argument("closed_forms: Poisson's ratio 'nu' must lie in (-1, 0.5), got " +
                                  format_number(nu));
    const double A = coefficient_A(a, b, p_i, p_o), B = coefficient_B(a, b, p_i, p_o);
    // From eps_r = du/dr, eps_theta = u/r and the stresses A -+ B/r^2 (sigma_r(a) = -p_i).
    if (plane_strain)
      return (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r);
    return ((1 - nu) * A * r + (1 + nu) * B / r) / E;
  }

  double lame_radial_stress(const double a, const double b, const double p_i, const double p_o,
                            const double r)
  {
    check_radii(a, b, r);
    return coefficient_A(a, b, p_i, p_o) - coefficient_B(a, b, p_i, p_o) / (r * r);
  }

  double lame_hoop_stress(const double a, const double b, const double p_i, const double p_o,
                          const double r)
  {
    check_radii(a, b, r);
    return coefficient_A(a, b, p_i, p_o) + coefficient_B(a, b, p_i, p_o) / (r * r);
  }
} // namespace closed_forms
