// Rainflow counting against ASTM E1049-85 and against properties any correct count must have.
#include <fatigue/rainflow.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

namespace
{
  // Count per range; ranges here are integers or exact sums of binary fractions, so exact keys.
  std::map<double, double>
  counts_by_range(const std::vector<fatigue::CountedCycle> &cycles)
  {
    std::map<double, double> counts;
    for (const auto &c : cycles)
      counts[c.range()] += c.count;
    return counts;
  }

  std::map<std::pair<double, double>, double>
  counts_by_range_and_mean(const std::vector<fatigue::CountedCycle> &cycles)
  {
    std::map<std::pair<double, double>, double> counts;
    for (const auto &c : cycles)
      counts[{c.range(), c.mean()}] += c.count;
    return counts;
  }

  std::vector<double>
  random_history(std::mt19937 &generator, const std::size_t n)
  {
    // Integer levels make equal ranges (ties X = Y) frequent, the delicate case of the rules.
    std::uniform_int_distribution<int> level(-10, 10);
    std::vector<double>                history(n);
    for (double &x : history)
      x = level(generator);
    return history;
  }

  const std::vector<double> astm_history{-2, 1, -3, 5, -1, 3, -4, 4, -2};
} // namespace

// ASTM E1049-85, 5.4.4 and its Fig. 6 / Table 4 (rainflow counting): the history
// A..I = -2, 1, -3, 5, -1, 3, -4, 4, -2 gives
//   range 3: 0.5, range 4: 1.5, range 6: 0.5, range 8: 1.0, range 9: 0.5 cycles
// and nothing at ranges 1, 2, 5, 7, 10. We checked this table by stepping through the standard's
// rules by hand: A-B half (3), B-C half (4), E-F full (4), C-D half (8), then the residue D-G (9),
// G-H (8), H-I (6) as halves.
TEST(Rainflow, AstmE1049WorkedExampleExact)
{
  const auto cycles = fatigue::count_cycles(astm_history, fatigue::HistoryKind::single_pass);
  const std::map<double, double> expected{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}};
  EXPECT_EQ(counts_by_range(cycles), expected);
  EXPECT_EQ(fatigue::total_count(cycles), 4.0);
}

// The same hand derivation gives the means (not tabulated by the standard): A-B (-2, 1) -0.5,
// B-C (1, -3) -1, E-F (-1, 3) 1, C-D (-3, 5) 1, D-G (5, -4) 0.5, G-H (-4, 4) 0, H-I (4, -2) 1.
TEST(Rainflow, AstmE1049WorkedExampleMeansAndOrder)
{
  const auto cycles = fatigue::count_rainflow(fatigue::extract_reversals(astm_history));
  const std::vector<std::tuple<std::size_t, std::size_t, double>> expected{
      {0, 1, 0.5}, {1, 2, 0.5}, {4, 5, 1.0}, {2, 3, 0.5}, {3, 6, 0.5}, {6, 7, 0.5}, {7, 8, 0.5}};
  ASSERT_EQ(cycles.size(), expected.size());
  for (std::size_t i = 0; i < cycles.size(); ++i)
    {
      EXPECT_EQ(cycles[i].from.index, std::get<0>(expected[i])) << i;
      EXPECT_EQ(cycles[i].to.index, std::get<1>(expected[i])) << i;
      EXPECT_EQ(cycles[i].count, std::get<2>(expected[i])) << i;
    }
  const std::vector<double> means{-0.5, -1.0, 1.0, 1.0, 0.5, 0.0, 1.0};
  for (std::size_t i = 0; i < cycles.size(); ++i)
    EXPECT_EQ(cycles[i].mean(), means[i]) << i;
}

// ASTM E1049-85 5.4.5 (simplified rainflow for a repeating history) on the same history, derived by
// hand: rotate to the largest magnitude, 5 (D): 5, -1, 3, -4, 4, -2, [-2 joins], 1, -3, 5. Counting
// removes (-1, 3) range 4, (-2, 1) range 3, (4, -3) range 7 and finally (5, -4) range 9, each a
// full cycle, nothing left over.
TEST(Rainflow, AstmE1049RepeatingHistory)
{
  const auto cycles = fatigue::count_cycles(astm_history, fatigue::HistoryKind::repeating);
  const std::map<double, double> expected{{3, 1.0}, {4, 1.0}, {7, 1.0}, {9, 1.0}};
  EXPECT_EQ(counts_by_range(cycles), expected);
  for (const auto &c : cycles)
    EXPECT_EQ(c.count, 1.0);
}

// In the three-point method every reversal but the last starts exactly one half cycle (each count
// consumes the first point of its range), so 2 * (total count) = reversals - 1.
TEST(Rainflow, HalfCyclesEqualReversalsMinusOne)
{
  std::mt19937 generator(20240611);
  for (int trial = 0; trial < 200; ++trial)
    {
      const auto history   = random_history(generator, 2 + trial);
      const auto reversals = fatigue::extract_reversals(history);
      const auto cycles    = fatigue::count_rainflow(reversals);
      EXPECT_EQ(2.0 * fatigue::total_count(cycles), static_cast<double>(reversals.size() - 1))
          << "trial " << trial;
    }
}

// The largest range of the record (max - min) is always counted, at least as a half cycle.
TEST(Rainflow, LargestRangeIsAlwaysCounted)
{
  std::mt19937 generator(7);
  for (int trial = 0; trial < 100; ++trial)
    {
      const auto history = random_history(generator, 3 + trial);
      double     lo = history[0], hi = history[0];
      for (const double x : history)
        lo = std::min(lo, x), hi = std::max(hi, x);
      if (hi == lo)
        continue;
      const auto counts =
          counts_by_range(fatigue::count_cycles(history, fatigue::HistoryKind::single_pass));
      ASSERT_EQ(counts.rbegin()->first, hi - lo) << "trial " << trial;
    }
}

// The two variants of the standard are consistent: a single-pass count (5.4.4) of a period repeated
// R times differs from R periods only at the ends, so each extra period adds exactly the cycles of
// the repeating count (5.4.5), same ranges and means.
TEST(Rainflow, SinglePassOfRepeatedPeriodsAgreesWithRepeatingCount)
{
  std::mt19937 generator(42);
  for (int trial = 0; trial < 50; ++trial)
    {
      const auto period = random_history(generator, 3 + trial);
      const auto periodic =
          counts_by_range_and_mean(fatigue::count_cycles(period, fatigue::HistoryKind::repeating));

      auto repeat = [&](const int times) {
        std::vector<double> history;
        for (int r = 0; r < times; ++r)
          history.insert(history.end(), period.begin(), period.end());
        return counts_by_range_and_mean(
            fatigue::count_cycles(history, fatigue::HistoryKind::single_pass));
      };
      auto       difference = repeat(11);
      const auto ten        = repeat(10);
      for (const auto &[key, count] : ten)
        difference[key] -= count;
      for (auto it = difference.begin(); it != difference.end();)
        it = (it->second == 0.0) ? difference.erase(it) : std::next(it);
      EXPECT_EQ(difference, periodic) << "trial " << trial;
    }
}

TEST(Rainflow, SampledSineCountsOneCyclePerPeriod)
{
  const double        amplitude = 0.03, mean = 0.01;
  const int           periods = 5, samples_per_period = 48;
  std::vector<double> history;
  for (int i = 0; i < periods * samples_per_period; ++i)
    history.push_back(mean + amplitude * std::sin(2.0 * M_PI * i / samples_per_period));
  const auto cycles = fatigue::count_cycles(history, fatigue::HistoryKind::repeating);
  ASSERT_EQ(cycles.size(), static_cast<std::size_t>(periods));
  for (const auto &c : cycles)
    {
      // Samples at i = 12 and 36 of each period hit the crests exactly (up to sin round-off).
      EXPECT_NEAR(c.range(), 2.0 * amplitude, 1e-15);
      EXPECT_NEAR(c.mean(), mean, 1e-15);
      EXPECT_EQ(c.count, 1.0);
    }
}

TEST(Rainflow, TabulateMergesEqualRangeAndMean)
{
  const auto rows =
      fatigue::tabulate(fatigue::count_cycles({0, 2, 0, 2, 0, 5}, fatigue::HistoryKind::repeating));
  // Rotated at 5: 5, 0, 2, 0, 2, 0, 5 -> (0, 2) twice, then (5, 0) once.
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].range, 5.0);
  EXPECT_EQ(rows[0].mean, 2.5);
  EXPECT_EQ(rows[0].count, 1.0);
  EXPECT_EQ(rows[1].range, 2.0);
  EXPECT_EQ(rows[1].mean, 1.0);
  EXPECT_EQ(rows[1].count, 2.0);
}

// Cycles that differ only by round-off in range and mean end up in one row.
TEST(Rainflow, TabulateMergesRoundOffDifferences)
{
  using fatigue::CountedCycle;
  const double              e = 1e-16;
  std::vector<CountedCycle> cycles{{{0, 0.0}, {1, 2.0 + e}, 1.0},
                                   {{2, 0.0 + e}, {3, 2.0}, 1.0},
                                   {{4, 0.0}, {5, 2.0}, 0.5},
                                   {{6, 1.0}, {7, 3.0}, 1.0}};
  const auto                rows = fatigue::tabulate(cycles);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].count, 1.0); // range 2 around mean 2
  EXPECT_EQ(rows[1].count, 2.5); // range 2 around mean 1, three round-off variants
}

TEST(Rainflow, RepeatingCountRejectsAnOpenSequence)
{
  EXPECT_THROW(fatigue::count_rainflow_repeating(fatigue::extract_reversals({0, 1, 0, 2})),
               std::invalid_argument);
  EXPECT_TRUE(fatigue::count_cycles({3, 3, 3}, fatigue::HistoryKind::repeating).empty());
  EXPECT_TRUE(fatigue::count_cycles({3}, fatigue::HistoryKind::single_pass).empty());
}
