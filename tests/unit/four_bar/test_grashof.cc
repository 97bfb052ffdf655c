// Grashof classes on textbook linkages, and the class's mobility claim checked independently by
// trying to assemble the linkage at every crank (or rocker) angle.
#include <mechanisms/four_bar/grashof.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

namespace
{
  // Can the input link (crank at A) be placed at every angle? (Assembly, not classification.)
  bool input_turns_fully(const LinkLengths &l)
  {
    for (double th2_deg = 0.; th2_deg < 360.; th2_deg += 0.5)
      try
        {
          solve_pose(l, th2_deg * deg, AssemblyBranch::plus);
        }
      catch (const std::domain_error &)
        {
          return false;
        }
    return true;
  }

  // The same linkage seen from D: the rocker becomes the input (mirror the chain).
  LinkLengths swap_input_and_output(const LinkLengths &l)
  {
    return {l.ground, l.rocker, l.coupler, l.crank};
  }

  struct Case
  {
    LinkLengths  lengths;
    GrashofClass expected;
    const char  *name;
  };

  // Norton, Design of Machinery, Example 4-1 (6, 2, 7, 9) and its inversions, which keep the
  // same s + l < p + q and move the shortest link (Norton Fig. 2-16); a parallelogram and the
  // flap (change points); a non-Grashof chain.
  const Case textbook_cases[] = {
    {{6., 2., 7., 9.}, GrashofClass::crank_rocker, "Norton Ex. 4-1"},
    {{2., 6., 7., 9.}, GrashofClass::double_crank, "ground shortest"},
    {{6., 7., 2., 9.}, GrashofClass::double_rocker, "coupler shortest"},
    {{6., 9., 7., 2.}, GrashofClass::rocker_crank, "rocker shortest"},
    {{5., 2., 5., 2.}, GrashofClass::change_point, "parallelogram"},
    {{0.060, 0.010, 0.065, 0.015}, GrashofClass::change_point, "flap (paper Table 1)"},
    {{7., 3., 4., 5.}, GrashofClass::triple_rocker, "s + l > p + q"}};
} // namespace

TEST(Grashof, ClassifiesTextbookLinkages)
{
  for (const Case &c : textbook_cases)
    EXPECT_EQ(classify_grashof(c.lengths).class_, c.expected)
      << c.name << ": got " << to_string(classify_grashof(c.lengths).class_);
}

TEST(Grashof, MobilityClaimAgreesWithAssembly)
{
  for (const Case &c : textbook_cases)
    {
      const GrashofAnalysis g = classify_grashof(c.lengths);
      EXPECT_EQ(g.crank_fully_rotates, input_turns_fully(c.lengths)) << c.name;
      EXPECT_EQ(g.rocker_fully_rotates, input_turns_fully(swap_input_and_output(c.lengths)))
        << c.name;
    }
}

TEST(Grashof, FlapIsAChangePointCrankRocker)
{
  const GrashofAnalysis g = classify_grashof(flap_linkage());
  EXPECT_EQ(g.grashof_limit_class, GrashofClass::crank_rocker);
  EXPECT_NEAR(g.condition, 0., 1e-17);
}

TEST(Grashof, EqualityToleranceSeparatesTheClasses)
{
  // 1 um on 65 mm is far outside the 1e-9 relative tolerance.
  EXPECT_EQ(classify_grashof({0.060, 0.010, 0.065, 0.015001}).class_, GrashofClass::crank_rocker);
  EXPECT_EQ(classify_grashof({0.060, 0.010, 0.065001, 0.015}).class_, GrashofClass::triple_rocker);
  EXPECT_THROW(classify_grashof({0.060, 0., 0.065, 0.015}), std::invalid_argument);
}
