#include <fatigue/input_checks.h>
#include <fatigue/life_curve.h>

#include <cmath>
#include <limits>

namespace fatigue
{
  void
  LifeCurve::check() const
  {
    const std::string prefix = "life curve '" + name + "': ";
    internal::require_positive(prefix + "reference_amplitude", reference_amplitude);
    internal::require_positive(prefix + "reference_cycles", reference_cycles);
    internal::require_positive(prefix + "exponent", exponent);
    internal::require_non_negative(prefix + "endurance_amplitude", endurance_amplitude);
  }

  double
  LifeCurve::damage_per_cycle(const double equivalent_amplitude) const
  {
    check();
    if (std::isinf(equivalent_amplitude) && equivalent_amplitude > 0.0)
      return std::numeric_limits<double>::infinity(); // e.g. Goodman with mean >= ultimate
    internal::require_non_negative("equivalent_amplitude", equivalent_amplitude);
    if (equivalent_amplitude == 0.0 || equivalent_amplitude <= endurance_amplitude)
      return 0.0;
    return std::pow(equivalent_amplitude / reference_amplitude, exponent) / reference_cycles;
  }

  double
  LifeCurve::cycles_to_failure(const double equivalent_amplitude) const
  {
    const double d = damage_per_cycle(equivalent_amplitude);
    return d == 0.0 ? std::numeric_limits<double>::infinity() : 1.0 / d;
  }

  double
  LifeCurve::amplitude_at(const double cycles) const
  {
    check();
    internal::require_positive("cycles", cycles);
    return reference_amplitude * std::pow(cycles / reference_cycles, -1.0 / exponent);
  }

  LifeCurve
  LifeCurve::scaled(const double factor, const std::string &new_name) const
  {
    internal::require_positive("factor", factor);
    LifeCurve result = *this;
    result.name      = new_name;
    result.reference_amplitude *= factor;
    result.endurance_amplitude *= factor;
    return result;
  }
} // namespace fatigue
