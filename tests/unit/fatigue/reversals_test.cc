// Reversal extraction: expected turning points are worked out by hand from each history.
#include <fatigue/reversals.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace
{
  using fatigue::Reversal;

  void
  expect_reversals(const std::vector<Reversal>                       &actual,
                   const std::vector<std::pair<std::size_t, double>> &expected)
  {
    ASSERT_EQ(actual.size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      {
        EXPECT_EQ(actual[i].index, expected[i].first) << "reversal " << i;
        EXPECT_EQ(actual[i].value, expected[i].second) << "reversal " << i;
      }
  }
} // namespace

TEST(Reversals, AstmExampleIsAlreadyAReversalSequence)
{
  const std::vector<double> history{-2, 1, -3, 5, -1, 3, -4, 4, -2};
  const auto                reversals = fatigue::extract_reversals(history);
  ASSERT_EQ(reversals.size(), history.size());
  for (std::size_t i = 0; i < history.size(); ++i)
    EXPECT_EQ(reversals[i].index, i);
}

TEST(Reversals, DropsPointsOnSlopesAndPlateausKeepsEnds)
{
  // Rises 0..3 (i = 4), falls through a plateau 1, 1 to 0 (i = 7), rises to the last sample 2.
  expect_reversals(fatigue::extract_reversals({0, 1, 2, 2, 3, 1, 1, 0, 2}),
                   {{0, 0.0}, {4, 3.0}, {7, 0.0}, {8, 2.0}});
  // A plateau at a peak is represented by its first sample.
  expect_reversals(fatigue::extract_reversals({0, 2, 2, 2, 1}), {{0, 0.0}, {1, 2.0}, {4, 1.0}});
  // A record that ends mid-slope ends on its last sample.
  expect_reversals(fatigue::extract_reversals({0, 5, 3}), {{0, 0.0}, {1, 5.0}, {2, 3.0}});
}

TEST(Reversals, ConstantHistoryHasOneReversal)
{
  expect_reversals(fatigue::extract_reversals({1.5, 1.5, 1.5}), {{0, 1.5}});
  expect_reversals(fatigue::extract_reversals({7.0}), {{0, 7.0}});
}

TEST(Reversals, GateRemovesSmallExcursionsOnly)
{
  const std::vector<double> history{0, 5, 4.5, 5.2, 0};
  // Without a gate the 0.7 dip is a valley-peak pair ...
  expect_reversals(fatigue::extract_reversals(history),
                   {{0, 0.0}, {1, 5.0}, {2, 4.5}, {3, 5.2}, {4, 0.0}});
  // ... with a gate of 1 it disappears and the peak is the higher of the two.
  expect_reversals(fatigue::extract_reversals(history, 1.0), {{0, 0.0}, {3, 5.2}, {4, 0.0}});
  // A small excursion at the start is filtered too: the first reversal is the valley -0.5.
  expect_reversals(fatigue::extract_reversals({0, -0.5, 5, 0}, 1.0),
                   {{1, -0.5}, {2, 5.0}, {3, 0.0}});
  // Everything within the gate: nothing left to count.
  EXPECT_EQ(fatigue::extract_reversals({0, 0.3, -0.2, 0.1}, 1.0).size(), 1u);
}

TEST(Reversals, RepeatingHistoryStartsAndEndsAtLargestMagnitude)
{
  // |-5| is the largest magnitude (index 2). Rotated: -5, 2, 1, 0, 3, -5: the 1 lies on a slope.
  expect_reversals(fatigue::extract_repeating_reversals({0, 3, -5, 2, 1}),
                   {{2, -5.0}, {3, 2.0}, {0, 0.0}, {1, 3.0}, {2, -5.0}});
  // A junction between last and first sample that lies on a slope disappears: 1 -> 2 -> 3 -> 1.
  expect_reversals(fatigue::extract_repeating_reversals({2, 3, 1}), {{1, 3.0}, {2, 1.0}, {1, 3.0}});
}

TEST(Reversals, BadInputThrowsNamingTheParameter)
{
  EXPECT_THROW(fatigue::extract_reversals({}), std::invalid_argument);
  EXPECT_THROW(fatigue::extract_repeating_reversals({}), std::invalid_argument);
  try
    {
      fatigue::extract_reversals({0.0, std::numeric_limits<double>::quiet_NaN()});
      FAIL() << "NaN accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("history[1]"), std::string::npos) << e.what();
    }
  try
    {
      fatigue::extract_reversals({0.0, 1.0}, -1.0);
      FAIL() << "negative gate accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("'gate'"), std::string::npos) << e.what();
    }
}
