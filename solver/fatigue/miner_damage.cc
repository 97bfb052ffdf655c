#include <fatigue/input_checks.h>
#include <fatigue/miner_damage.h>

#include <cmath>
#include <limits>

namespace fatigue
{
  LoadingSpectrum
  equivalent_spectrum(const std::vector<CountedCycle> &cycles,
                      const MeanCorrectionSettings    &correction)
  {
    correction.check();
    LoadingSpectrum spectrum;
    spectrum.reserve(cycles.size());
    for (const CountedCycle &cycle : cycles)
      spectrum.push_back({equivalent_amplitude(cycle, correction), cycle.count});
    return spectrum;
  }

  double
  miner_damage(const LoadingSpectrum &spectrum, const LifeCurve &curve)
  {
    curve.check();
    double damage = 0.0;
    for (const AmplitudeCount &entry : spectrum)
      {
        internal::require_non_negative("count", entry.count);
        if (entry.count > 0.0)
          damage += entry.count * curve.damage_per_cycle(entry.amplitude);
      }
    return damage;
  }

  double
  repeats_to_failure(const double damage_per_repeat)
  {
    if (std::isinf(damage_per_repeat) && damage_per_repeat > 0.0)
      return 0.0;
    internal::require_non_negative("damage_per_repeat", damage_per_repeat);
    return damage_per_repeat == 0.0 ? std::numeric_limits<double>::infinity()
                                    : 1.0 / damage_per_repeat;
  }
} // namespace fatigue
