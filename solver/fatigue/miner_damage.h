// Palmgren-Miner linear damage accumulation: D = sum_i n_i / N_i, failure at D = 1
// (A. Palmgren, VDI-Z. 68:339-341, 1924; M. A. Miner, J. Appl. Mech. 12:A159-A164, 1945).
// Load sequence and small-cycle interaction effects are ignored: that is the rule, not a bug.
#ifndef FATIGUE_MINER_DAMAGE_H
#define FATIGUE_MINER_DAMAGE_H

#include <fatigue/life_curve.h>
#include <fatigue/mean_correction.h>
#include <fatigue/rainflow.h>

#include <vector>

namespace fatigue
{
  // n_i cycles (0.5 for a half cycle) at equivalent amplitude a_i.
  struct AmplitudeCount
  {
    double amplitude;
    double count;
  };
  using LoadingSpectrum = std::vector<AmplitudeCount>;

  // Counted cycles -> equivalent amplitudes through the mean correction, in the same order.
  LoadingSpectrum
  equivalent_spectrum(const std::vector<CountedCycle> &cycles,
                      const MeanCorrectionSettings    &correction);

  // D = sum n_i / N(a_i). Throws std::invalid_argument on a negative count.
  double
  miner_damage(const LoadingSpectrum &spectrum, const LifeCurve &curve);

  // Repeats of a history with damage D per repeat until D = 1: 1 / D; +infinity if D = 0.
  double
  repeats_to_failure(double damage_per_repeat);
} // namespace fatigue

#endif
