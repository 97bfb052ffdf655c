#include <fatigue/input_checks.h>
#include <fatigue/reversals.h>

#include <cmath>

namespace fatigue
{
  namespace
  {
    void
    check_history(const std::vector<double> &history, const double gate)
    {
      if (history.empty())
        throw std::invalid_argument(
            "fatigue: parameter 'history' must hold at least one sample, got "
            "an empty history");
      for (std::size_t i = 0; i < history.size(); ++i)
        internal::require_finite("history[" + std::to_string(i) + "]", history[i]);
      internal::require_non_negative("gate", gate);
    }

    // Hysteresis filter on samples that are known to be finite. Returns reversal positions in the
    // given sequence.
    std::vector<Reversal>
    filter_turning_points(const std::vector<double> &values, const double gate)
    {
      std::vector<Reversal> reversals;
      const std::size_t     n = values.size();

      // Until the signal has moved by more than the gate its direction is unknown: track the
      // lowest and highest samples seen; whichever came first is the first reversal. Strict
      // comparisons keep the first sample of a plateau.
      std::size_t i_min = 0, i_max = 0, i = 1;
      int         direction = 0;
      Reversal    candidate{0, values[0]};
      for (; i < n; ++i)
        {
          if (values[i] > values[i_max])
            i_max = i;
          if (values[i] < values[i_min])
            i_min = i;
          if (values[i_max] - values[i_min] > gate)
            {
              if (i_max > i_min)
                {
                  reversals.push_back({i_min, values[i_min]});
                  candidate = {i_max, values[i_max]};
                  direction = +1;
                }
              else
                {
                  reversals.push_back({i_max, values[i_max]});
                  candidate = {i_min, values[i_min]};
                  direction = -1;
                }
              ++i;
              break;
            }
        }
      if (direction == 0)
        return {{0, values[0]}}; // flat within the gate: nothing to count

      // The candidate extreme is confirmed once the signal has come back from it by more than the
      // gate.
      for (; i < n; ++i)
        {
          const double x = values[i];
          if (direction > 0)
            {
              if (x > candidate.value)
                candidate = {i, x};
              else if (candidate.value - x > gate)
                {
                  reversals.push_back(candidate);
                  candidate = {i, x};
                  direction = -1;
                }
            }
          else
            {
              if (x < candidate.value)
                candidate = {i, x};
              else if (x - candidate.value > gate)
                {
                  reversals.push_back(candidate);
                  candidate = {i, x};
                  direction = +1;
                }
            }
        }
      reversals.push_back(candidate); // the end of the record is a reversal
      return reversals;
    }
  } // namespace

  std::vector<Reversal>
  extract_reversals(const std::vector<double> &history, const double gate)
  {
    check_history(history, gate);
    return filter_turning_points(history, gate);
  }

  std::vector<Reversal>
  extract_repeating_reversals(const std::vector<double> &one_period, const double gate)
  {
    check_history(one_period, gate);
    const std::size_t n = one_period.size();

    std::size_t i_extreme = 0;
    for (std::size_t i = 1; i < n; ++i)
      if (std::abs(one_period[i]) > std::abs(one_period[i_extreme]))
        i_extreme = i;

    // One period starting at the extreme and closed by the same sample of the next period.
    std::vector<double> rotated(n + 1);
    for (std::size_t j = 0; j <= n; ++j)
      rotated[j] = one_period[(i_extreme + j) % n];

    std::vector<Reversal> reversals = filter_turning_points(rotated, gate);
    for (Reversal &r : reversals)
      r.index = (i_extreme + r.index) % n;

    // The record starts on the extreme and the closing sample equals it, so the hysteresis filter
    // always ends on it: the last excursion back to the extreme is at least as large as the one
    // that confirmed the preceding turning point.
    if (reversals.back().value != reversals.front().value)
      throw std::logic_error("fatigue: repeating reversals do not close on the extreme");
    return reversals;
  }

  std::vector<double>
  reversal_values(const std::vector<Reversal> &reversals)
  {
    std::vector<double> values;
    values.reserve(reversals.size());
    for (const Reversal &r : reversals)
      values.push_back(r.value);
    return values;
  }
} // namespace fatigue
