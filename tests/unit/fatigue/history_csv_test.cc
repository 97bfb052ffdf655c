// CSV reading: accepted layout and the messages for each kind of bad input.
#include <fatigue/history_csv.h>

#include <gtest/gtest.h>

#include <sstream>
#include <stdexcept>

namespace
{
  fatigue::HistoryTable
  parse(const std::string &text)
  {
    std::istringstream input(text);
    return fatigue::parse_history_csv(input, "test.csv");
  }

  // Parses, expects failure, and checks that the message contains every given fragment.
  void
  expect_error(const std::string &text, const std::vector<std::string> &fragments)
  {
    try
      {
        parse(text);
        FAIL() << "accepted:\n" << text;
      }
    catch (const std::invalid_argument &e)
      {
        for (const std::string &fragment : fragments)
          EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos)
              << "'" << fragment << "' missing from: " << e.what();
      }
  }
} // namespace

TEST(HistoryCsv, ReadsHeaderColumnsCommentsAndBlankLines)
{
  const auto table = parse("# from the FE solver\n"
                           " step , \"A top\", B_bottom\n"
                           "\n"
                           "0, 0.0, -0.01\n"
                           "1, 1.5e-2, 0.02  \r\n"
                           "# mid-file comment\n"
                           "2, 0.0, -0.01\n");
  EXPECT_EQ(table.step_column, "step");
  ASSERT_EQ(table.hot_spots.size(), 2u);
  EXPECT_EQ(table.hot_spots[0].name, "A top");
  EXPECT_EQ(table.hot_spots[1].name, "B_bottom");
  EXPECT_EQ(table.steps, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(table.hot_spots[0].values, (std::vector<double>{0.0, 0.015, 0.0}));
  EXPECT_EQ(table.hot_spots[1].values, (std::vector<double>{-0.01, 0.02, -0.01}));
}

TEST(HistoryCsv, ErrorsNameFileLineColumnAndExpectation)
{
  expect_error("time,A\n0,0\n1,x\n",
               {"test.csv", "line 3", "column 'A'", "'x' is not a finite number"});
  expect_error("time,A\n0,0\n1,nan\n", {"line 3", "'nan' is not a finite number"});
  expect_error("time,A,B\n0,0,0\n1,2\n", {"line 3", "found 2 values (expected 3"});
  expect_error("time,A\n0,0\n0,1\n", {"line 3", "column 'time'", "strictly increasing"});
  expect_error("0,0.1\n1,0.2\n", {"line 1", "header is missing"});
  expect_error("time\n0\n1\n", {"time/step column and at least one hot-spot column"});
  expect_error("time,A,A\n0,0,0\n1,1,1\n", {"'A' appears twice"});
  expect_error("time,,B\n0,0,0\n1,1,1\n", {"column 2 of the header has no name"});
  expect_error("time,A\n0,0\n", {"found 1 data row", "at least 2 samples"});
  expect_error("# nothing\n", {"test.csv", "no header found"});
}

TEST(HistoryCsv, SelectColumnsKeepsRequestedOrderAndNamesTheMissingOne)
{
  const auto table    = parse("t,a,b,c\n0,1,2,3\n1,4,5,6\n");
  const auto selected = fatigue::select_columns(table, {"c", "a"});
  ASSERT_EQ(selected.hot_spots.size(), 2u);
  EXPECT_EQ(selected.hot_spots[0].name, "c");
  EXPECT_EQ(selected.hot_spots[1].values, (std::vector<double>{1, 4}));
  try
    {
      fatigue::select_columns(table, {"d"});
      FAIL() << "unknown column accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("column 'd' not found (expected one of the hot-spot "
                                           "columns 'a', 'b', 'c')"),
                std::string::npos)
          << e.what();
    }
}

TEST(HistoryCsv, MissingFileIsReported)
{
  try
    {
      fatigue::read_history_csv("/nonexistent/history.csv");
      FAIL() << "missing file accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("'/nonexistent/history.csv': cannot be opened"),
                std::string::npos)
          << e.what();
    }
}
