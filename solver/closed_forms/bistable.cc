#include "bistable.h"

#include "input_checks.h"

namespace closed_forms
{
  namespace
  {
    double rigidity_over_cube(const double L, const double E, const double b, const double t, const double h)
    {
      internal::require_positive("L", L);
      internal::require_positive("E", E);
      internal::require_positive("b", b);
      internal::require_positive("t", t);
      internal::require_positive("h", h);
      return E * b * t * t * t / 12.0 * h / (L * L * L);
    }
  } // namespace

  double bistable_switching_force_top(const double L, const double E, const double b, const double t, const double h)
  {
    return 740.0 * rigidity_over_cube(L, E, b, t, h);
  }

  double bistable_switching_force_bottom(const double L, const double E, const double b, const double t,
                                         const double h)
  {
    return 370.0 * rigidity_over_cube(L, E, b, t, h);
  }
} // namespace closed_forms
