// Rainflow cycle counting, ASTM E1049-85 (reapproved 2017), "Standard Practices for Cycle Counting
// in Fatigue Analysis":
//   - section 5.4.4, rainflow counting of a single-pass history (three-point method; ranges that
//     contain the starting point and the residue left at the end are counted as half cycles);
//   - section 5.4.5, simplified rainflow counting for a repeating history (the period is rotated to
//     start and end at its extreme, so every count is a closed cycle).
// Both take the reversals of the history (see reversals.h), never the raw samples.
#ifndef FATIGUE_RAINFLOW_H
#define FATIGUE_RAINFLOW_H

#include <fatigue/reversals.h>

#include <cstddef>
#include <vector>

namespace fatigue
{
  // One counted range: 0.5 (half cycle) or 1.0 (cycle). `from` and `to` are the two reversals that
  // bound the range, in time order of the (rotated, for repeating histories) reversal sequence.
  struct CountedCycle
  {
    Reversal from;
    Reversal to;
    double   count;

    double
    range() const;
    double
    mean() const;
    double
    amplitude() const; // range / 2
    double
    maximum() const;
    double
    minimum() const;
  };

  // ASTM E1049-85 5.4.4. Counts are reported in the order in which the standard extracts them.
  std::vector<CountedCycle>
  count_rainflow(const std::vector<Reversal> &reversals);

  // ASTM E1049-85 5.4.5. Expects the output of extract_repeating_reversals (first and last values
  // equal, the period's extreme); throws std::invalid_argument otherwise.
  std::vector<CountedCycle>
  count_rainflow_repeating(const std::vector<Reversal> &reversals);

  // How a history is to be read when counting it.
  enum class HistoryKind
  {
    single_pass, // counted once, residue as half cycles (5.4.4)
    repeating    // one period of a history that repeats (5.4.5); the duty cycle of a mechanism
  };

  // Reversal extraction followed by the matching rainflow variant.
  std::vector<CountedCycle>
  count_cycles(const std::vector<double> &history, HistoryKind kind, double gate = 0.0);

  // Sum of counts (a half cycle counts 0.5).
  double
  total_count(const std::vector<CountedCycle> &cycles);

  // A rainflow table: cycles of equal range and mean (within relative_tolerance of the largest
  // range) merged, sorted by decreasing range, then decreasing mean.
  struct RainflowTableRow
  {
    double range;
    double mean;
    double count;
  };

  std::vector<RainflowTableRow>
  tabulate(const std::vector<CountedCycle> &cycles, double relative_tolerance = 1e-12);
} // namespace fatigue

#endif
