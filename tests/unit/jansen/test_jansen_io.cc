// Leg dimension files and the crank-turn CSV.
#include <mechanisms/jansen/jansen_csv.h>
#include <mechanisms/jansen/jansen_parameter_file.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace compliant::jansen;

namespace
{
  const std::string paper_leg = "# the paper's leg\n"
                                "set EA = 193.96\nset AB = 75\nset BC = 250\nset BG = 309.5\n"
                                "set CE = 207.5\nset DE = 200.5\nset CD = 279   # CDE\n"
                                "set EG = 196.5\nset DF = 197\nset FG = 183\nset GH = 245\n"
                                "set FH = 328\n\nset theta1 = 11.6\n";

  std::string error_of(const std::string &text)
  {
    std::istringstream in(text);
    try
      {
        read_link_lengths(in, "leg.prm");
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  }

  std::vector<std::string> split_csv(const std::string &line)
  {
    std::vector<std::string> cells;
    std::stringstream        s(line);
    std::string              cell;
    while (std::getline(s, cell, ','))
      cells.push_back(cell);
    return cells;
  }
} // namespace

TEST(JansenParameterFile, ReadsTheLegDimensions)
{
  std::istringstream      in(paper_leg);
  const JansenLinkLengths l = read_link_lengths(in, "leg.prm");
  EXPECT_EQ(l.cd, 279.);
  EXPECT_EQ(l.fh, 328.);
  EXPECT_NEAR(l.ground_angle, 11.6 * M_PI / 180., 1e-15);
}

TEST(JansenParameterFile, NamesTheLineOrKeyOfAnError)
{
  EXPECT_NE(error_of(paper_leg + "set XY = 3\n").find("leg.prm:16: unknown parameter 'XY'"),
            std::string::npos);
  EXPECT_NE(error_of(paper_leg + "set AB = 80\n").find("'AB' repeated"), std::string::npos);
  std::string no_fh = paper_leg;
  no_fh.replace(no_fh.find("set FH = 328\n"), 13, "");
  EXPECT_NE(error_of(no_fh).find("'FH' is missing"), std::string::npos);
  std::string bad_value = paper_leg;
  bad_value.replace(bad_value.find("set AB = 75"), 11, "set AB = 7x5");
  EXPECT_NE(error_of(bad_value).find("leg.prm:3: value of 'AB' must be a number"),
            std::string::npos);
  std::string negative = paper_leg;
  negative.replace(negative.find("set AB = 75"), 11, "set AB = -75");
  EXPECT_NE(error_of(negative).find("length AB must be a positive"), std::string::npos);
  EXPECT_NE(error_of(paper_leg + "EA 3\n").find("expected 'set <name> = <value>'"),
            std::string::npos);
}

// One row per crank angle 0..360 deg, every row as wide as the header, and the
// foot columns identical to the joint-H columns.
TEST(JansenCsv, HasOneConsistentRowPerCrankAngle)
{
  const unsigned int steps = 12;
  std::ostringstream out;
  write_crank_turn_csv(out, sweep_crank_turn(paper_link_lengths(), 10., steps));
  std::istringstream       in(out.str());
  std::string              line;
  std::getline(in, line);
  const auto header = split_csv(line);
  const auto column = [&](const std::string &name) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  ASSERT_LT(column("x_H"), header.size());
  unsigned int rows = 0;
  while (std::getline(in, line))
    {
      const auto cells = split_csv(line);
      ASSERT_EQ(cells.size(), header.size());
      EXPECT_NEAR(std::stod(cells[column("theta2_deg")]), 30. * rows, 1e-9);
      EXPECT_EQ(cells[1], cells[header.size() - 2]); // x_H
      EXPECT_EQ(cells[2], cells[header.size() - 1]); // y_H
      ++rows;
    }
  EXPECT_EQ(rows, steps + 1);
}
