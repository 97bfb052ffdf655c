#include <fatigue/input_checks.h>
#include <fatigue/rainflow.h>

#include <algorithm>
#include <cmath>

namespace fatigue
{
  double
  CountedCycle::range() const
  {
    return std::abs(to.value - from.value);
  }

  double
  CountedCycle::mean() const
  {
    return 0.5 * (to.value + from.value);
  }

  double
  CountedCycle::amplitude() const
  {
    return 0.5 * range();
  }

  double
  CountedCycle::maximum() const
  {
    return std::max(from.value, to.value);
  }

  double
  CountedCycle::minimum() const
  {
    return std::min(from.value, to.value);
  }

  std::vector<CountedCycle>
  count_rainflow(const std::vector<Reversal> &reversals)
  {
    // The standard's steps, with the working list of not-yet-discarded points as a stack. The
    // starting point S is always the bottom of the stack: it only moves when the bottom point is
    // discarded (step 5), and points above it are discarded in pairs (step 4).
    std::vector<CountedCycle> cycles;
    std::vector<Reversal>     stack;
    stack.reserve(reversals.size());

    for (const Reversal &next : reversals) // step 1: read next peak or valley
      {
        stack.push_back(next);
        while (stack.size() >= 3) // step 2: X from the newest two points, Y from the two before
          {
            const std::size_t n = stack.size();
            const double      x = std::abs(stack[n - 1].value - stack[n - 2].value);
            const double      y = std::abs(stack[n - 2].value - stack[n - 3].value);
            if (x < y) // step 3a
              break;
            if (n == 3) // step 5: Y contains the starting point
              {
                cycles.push_back({stack[0], stack[1], 0.5});
                stack.erase(stack.begin());
              }
            else // step 4: count Y as one cycle, discard its peak and valley
              {
                cycles.push_back({stack[n - 3], stack[n - 2], 1.0});
                stack.erase(stack.end() - 3, stack.end() - 1);
              }
          }
      }

    // Step 6: every range not yet counted is a half cycle.
    for (std::size_t i = 1; i < stack.size(); ++i)
      cycles.push_back({stack[i - 1], stack[i], 0.5});
    return cycles;
  }

  std::vector<CountedCycle>
  count_rainflow_repeating(const std::vector<Reversal> &reversals)
  {
    if (reversals.size() <= 1)
      return {};
    if (reversals.front().value != reversals.back().value)
      throw std::invalid_argument("fatigue: parameter 'reversals' of a repeating history must "
                                  "start and end at the period's "
                                  "extreme (use extract_repeating_reversals), got first value " +
                                  internal::format_number(reversals.front().value) +
                                  " and last value " +
                                  internal::format_number(reversals.back().value));

    // 5.4.5 steps 2-4: since the record starts at its extreme, a range containing the starting
    // point can only be closed by the final point, so there is no half-cycle rule.
    std::vector<CountedCycle> cycles;
    std::vector<Reversal>     stack;
    stack.reserve(reversals.size());
    for (const Reversal &next : reversals)
      {
        stack.push_back(next);
        while (stack.size() >= 3)
          {
            const std::size_t n = stack.size();
            const double      x = std::abs(stack[n - 1].value - stack[n - 2].value);
            const double      y = std::abs(stack[n - 2].value - stack[n - 3].value);
            if (x < y)
              break;
            cycles.push_back({stack[n - 3], stack[n - 2], 1.0});
            stack.erase(stack.end() - 3, stack.end() - 1);
          }
      }
    // Only the closing extreme is left by construction; anything else would be a logic error.
    if (stack.size() != 1)
      throw std::logic_error("fatigue: repeating rainflow count left an unclosed residue");
    return cycles;
  }

  std::vector<CountedCycle>
  count_cycles(const std::vector<double> &history, const HistoryKind kind, const double gate)
  {
    if (kind == HistoryKind::repeating)
      return count_rainflow_repeating(extract_repeating_reversals(history, gate));
    return count_rainflow(extract_reversals(history, gate));
  }

  double
  total_count(const std::vector<CountedCycle> &cycles)
  {
    double sum = 0.0;
    for (const CountedCycle &c : cycles)
      sum += c.count;
    return sum;
  }

  std::vector<RainflowTableRow>
  tabulate(const std::vector<CountedCycle> &cycles, const double relative_tolerance)
  {
    internal::require_non_negative("relative_tolerance", relative_tolerance);
    double largest = 0.0;
    for (const CountedCycle &c : cycles)
      largest = std::max({largest, c.range(), std::abs(c.mean())});
    const double tolerance = relative_tolerance * largest;

    // Group by range (sorted, within the tolerance of the group's first row), then by mean inside
    // each group: O(n log n) for long FE histories with many small cycles, and robust to round-off
    // in either coordinate.
    std::vector<RainflowTableRow> sorted;
    sorted.reserve(cycles.size());
    for (const CountedCycle &c : cycles)
      sorted.push_back({c.range(), c.mean(), c.count});
    std::sort(sorted.begin(), sorted.end(),
              [](const RainflowTableRow &a, const RainflowTableRow &b) {
                return a.range > b.range;
              });
    std::vector<RainflowTableRow> rows;
    for (std::size_t begin = 0; begin < sorted.size();)
      {
        std::size_t end = begin + 1;
        while (end < sorted.size() && sorted[begin].range - sorted[end].range <= tolerance)
          ++end;
        std::sort(sorted.begin() + begin, sorted.begin() + end,
                  [](const RainflowTableRow &a, const RainflowTableRow &b) {
                    return a.mean > b.mean;
                  });
        for (std::size_t i = begin; i < end; ++i)
          if (i > begin && rows.back().mean - sorted[i].mean <= tolerance)
            rows.back().count += sorted[i].count;
          else
            rows.push_back(sorted[i]);
        begin = end;
      }
    return rows;
  }
} // namespace fatigue
