#include "prbm.h"

#include "beams.h"
#include "input_checks.h"

#include <cmath>
#include <stdexcept>

namespace closed_forms
{
  using internal::require_finite;
  using internal::require_positive;

  // Howell 2001, sec. 5.2 (small-length flexural pivot).
  double
  prbm_pivot_stiffness(const double E, const double b, const double h, const double l)
  {
    require_positive("E", E);
    require_positive("l", l);
    return E * second_moment_of_area(b, h) / l;
  }

  // Howell 2001, sec. 5.3 (cantilever beam with force at the free end).
  double
  prbm_cantilever_force_stiffness(const double E, const double b, const double h, const double l,
                                  const double gamma, const double K_theta)
  {
    require_positive("E", E);
    require_positive("l", l);
    require_positive("gamma", gamma);
    require_positive("K_theta", K_theta);
    if (gamma > 1.0)
      throw std::invalid_argument(
        "closed_forms: parameter 'gamma' (characteristic radius factor) must be in (0, 1], got " +
        internal::format_number(gamma));
    return gamma * K_theta * E * second_moment_of_area(b, h) / l;
  }

  PlanarPoint
  prbm_cantilever_tip_position(const double l, const double Theta, const double gamma)
  {
    require_positive("l", l);
    require_finite("Theta", Theta);
    require_positive("gamma", gamma);
    return {l * (1.0 - gamma * (1.0 - std::cos(Theta))), gamma * l * std::sin(Theta)};
  }

  double
  prbm_cantilever_tip_force(const double E, const double b, const double h, const double l,
                            const double Theta, const double gamma, const double K_theta)
  {
    require_finite("Theta", Theta);
    if (!(std::abs(Theta) < 0.5 * M_PI))
      throw std::invalid_argument(
        "closed_forms: parameter 'Theta' must satisfy |Theta| < pi/2 (a transverse force cannot "
        "turn the link further), got " + internal::format_number(Theta));
    const double K = prbm_cantilever_force_stiffness(E, b, h, l, gamma, K_theta);
    return K * Theta / (gamma * l * std::cos(Theta));
  }
} // namespace closed_forms
