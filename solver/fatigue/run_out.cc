#include <fatigue/input_checks.h>
#include <fatigue/run_out.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fatigue
{
  namespace
  {
    // Damage of one spectrum under the curve with amplitudes scaled by s.
    double
    scaled_damage(const LoadingSpectrum &spectrum, const LifeCurve &curve, const double s)
    {
      return miner_damage(spectrum, curve.scaled(s, curve.name));
    }

    // inf { s > 0 : n D(s) <= 1 } for one spectrum; D(s) is non-increasing in s.
    double
    minimum_scale_for(const LoadingSpectrum &spectrum, const LifeCurve &curve, const double n)
    {
      const double damage = miner_damage(spectrum, curve);
      if (curve.endurance_amplitude == 0.0)
        // D(s) = s^-k D(1): closed form.
        return damage == 0.0 ? 0.0 : std::pow(n * damage, 1.0 / curve.exponent);

      // With an endurance limit D(s) is a sum of power laws that switch off one by one: bracket
      // and bisect on the predicate n D(s) <= 1 (the infimum, since D may jump).
      double largest = 0.0;
      for (const AmplitudeCount &entry : spectrum)
        if (entry.count > 0.0)
          largest = std::max(largest, entry.amplitude);
      if (largest == 0.0)
        return 0.0;
      double hi = 1.0;
      while (n * scaled_damage(spectrum, curve, hi) > 1.0)
        hi *= 2.0;
      double lo = hi;
      // All cycles do damage once s < largest / endurance; below that D grows without bound.
      while (n * scaled_damage(spectrum, curve, lo) <= 1.0)
        {
          lo *= 0.5;
          if (lo < 1e-300)
            return 0.0;
        }
      for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration)
        {
          const double mid                                           = 0.5 * (lo + hi);
          (n * scaled_damage(spectrum, curve, mid) <= 1.0 ? hi : lo) = mid;
        }
      return hi;
    }

    RunOutImplication
    finish(const LifeCurve &curve, const double survived, const double predicted,
           const double minimum_scale)
    {
      RunOutImplication result{curve,         survived,    predicted, predicted >= survived,
                               minimum_scale, std::nullopt};
      if (minimum_scale > 0.0)
        result.lower_bound = curve.scaled(minimum_scale, curve.name + " (run-out lower bound)");
      return result;
    }
  } // namespace

  LifeCurve
  RunOutImplication::constrained() const
  {
    if (consistent || !lower_bound)
      return curve;
    LifeCurve lifted = *lower_bound;
    lifted.name      = curve.name + " (lifted to run-out)";
    return lifted;
  }

  RunOutImplication
  implied_by_run_out(const LifeCurve &curve, const double equivalent_amplitude,
                     const double cycles_survived)
  {
    internal::require_positive("equivalent_amplitude", equivalent_amplitude);
    return implied_by_run_out(curve, {{{equivalent_amplitude, 1.0}}}, cycles_survived);
  }

  RunOutImplication
  implied_by_run_out(const LifeCurve &curve, const std::vector<LoadingSpectrum> &hot_spot_spectra,
                     const double repeats_survived)
  {
    curve.check();
    internal::require_positive("repeats_survived", repeats_survived);
    if (hot_spot_spectra.empty())
      throw std::invalid_argument("fatigue: parameter 'hot_spot_spectra' must hold at least one "
                                  "spectrum, got none");
    double worst_damage = 0.0, scale = 0.0;
    for (const LoadingSpectrum &spectrum : hot_spot_spectra)
      {
        worst_damage = std::max(worst_damage, miner_damage(spectrum, curve));
        scale        = std::max(scale, minimum_scale_for(spectrum, curve, repeats_survived));
      }
    return finish(curve, repeats_survived, repeats_to_failure(worst_damage), scale);
  }

  std::array<RunOutImplication, n_band_members>
  check_against_run_out(const FatigueModel                 &model,
                        const std::vector<LoadingSpectrum> &hot_spot_spectra,
                        const double                        repeats_survived)
  {
    model.check();
    return {implied_by_run_out(model.curves[low_life], hot_spot_spectra, repeats_survived),
            implied_by_run_out(model.curves[nominal_life], hot_spot_spectra, repeats_survived),
            implied_by_run_out(model.curves[high_life], hot_spot_spectra, repeats_survived)};
  }

  FatigueModel
  constrained_by_run_out(const FatigueModel                                  &model,
                         const std::array<RunOutImplication, n_band_members> &implications)
  {
    FatigueModel result = model;
    for (std::size_t m = 0; m < n_band_members; ++m)
      result.curves[m] = implications[m].constrained();
    result.name = model.name + " (constrained by run-out)";
    result.check();
    return result;
  }
} // namespace fatigue
