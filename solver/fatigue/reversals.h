// Reversal extraction (peak-valley filtering), the first step of ASTM E1049-85 cycle counting:
// only the turning points of a load history matter for rainflow counting, so intermediate points
// on a rising or falling stretch and repeated values (plateaus) are dropped.
#ifndef FATIGUE_REVERSALS_H
#define FATIGUE_REVERSALS_H

#include <cstddef>
#include <vector>

namespace fatigue
{
  // A turning point: its value and the index of the sample in the input history it came from.
  struct Reversal
  {
    std::size_t index;
    double      value;
  };

  // Peaks and valleys of a single-pass history. The first and last samples count as reversals, as
  // in the worked examples of ASTM E1049-85 where the record starts and ends on a counted point.
  //
  // gate >= 0 is a hysteresis (range) filter: a turning point is only accepted once the signal has
  // moved back from it by more than `gate`, so excursions of range <= gate vanish. gate = 0 is
  // plain peak-valley extraction. Throws std::invalid_argument on an empty history, a non-finite
  // sample or a negative gate.
  std::vector<Reversal>
  extract_reversals(const std::vector<double> &history, double gate = 0.0);

  // Reversals of one period of a history that repeats (ASTM E1049-85, 5.4.5 step 1): the period is
  // rotated to start at the sample of largest magnitude (highest peak or lowest valley) and closed
  // by repeating that sample, so that counting the result yields closed cycles only. Indices refer
  // to the unrotated input.
  std::vector<Reversal>
  extract_repeating_reversals(const std::vector<double> &one_period, double gate = 0.0);

  std::vector<double>
  reversal_values(const std::vector<Reversal> &reversals);
} // namespace fatigue

#endif
