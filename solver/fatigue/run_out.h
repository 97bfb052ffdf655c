// What a run-out (a test stopped without failure) says about a life curve. A run-out of n_s cycles
// at equivalent amplitude a_t only bounds the life from below: N(a_t) >= n_s. For a curve of fixed
// exponent k this bounds its reference amplitude from below,
//   a_ref >= a_t (n_s / N_ref)^(1/k),
// and through the assumed slope gives lower-bound lives elsewhere, N(a) >= n_s (a / a_t)^(-k). It
// says nothing about the slope, nor an upper bound on anything. For a repeated duty cycle at
// several hot spots, every hot spot survived n_s repeats, so the bound is set by the most damaged
// one:
//   the smallest factor s on the curve's amplitudes with n_s D_h(s) <= 1 for every hot spot h.
#ifndef FATIGUE_RUN_OUT_H
#define FATIGUE_RUN_OUT_H

#include <fatigue/fatigue_model.h>
#include <fatigue/life_curve.h>
#include <fatigue/miner_damage.h>

#include <array>
#include <optional>
#include <vector>

namespace fatigue
{
  struct RunOutImplication
  {
    LifeCurve curve;      // the curve that was checked
    double    survived;   // cycles (repeats) survived without failure
    double    predicted;  // the curve's life for the tested loading, same unit as survived
    bool      consistent; // predicted >= survived
    // Smallest factor on the curve's amplitudes that is consistent with the run-out (< 1 when the
    // curve has margin, > 1 when the curve predicts failure before the run-out); 0 when the loading
    // does no damage under any scaling.
    double minimum_scale;
    // The curve scaled by minimum_scale: the lower-bound curve of the same exponent (absent when
    // minimum_scale is 0).
    std::optional<LifeCurve> lower_bound;

    // The curve lifted to the lower bound where it contradicts the run-out, unchanged otherwise.
    LifeCurve
    constrained() const;
  };

  // Run-out of cycles_survived cycles at one equivalent amplitude.
  RunOutImplication
  implied_by_run_out(const LifeCurve &curve, double equivalent_amplitude, double cycles_survived);

  // Run-out of repeats_survived repeats of a duty cycle, one loading spectrum per hot spot.
  RunOutImplication
  implied_by_run_out(const LifeCurve &curve, const std::vector<LoadingSpectrum> &hot_spot_spectra,
                     double repeats_survived);

  // Every band member of a model checked against the same run-out.
  std::array<RunOutImplication, n_band_members>
  check_against_run_out(const FatigueModel                 &model,
                        const std::vector<LoadingSpectrum> &hot_spot_spectra,
                        double                              repeats_survived);

  // The model with each curve replaced by RunOutImplication::constrained().
  FatigueModel
  constrained_by_run_out(const FatigueModel                                  &model,
                         const std::array<RunOutImplication, n_band_members> &implications);
} // namespace fatigue

#endif
