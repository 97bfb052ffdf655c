// Position analysis: Freudenstein roots against an independent construction, loop closure at
// round-off, and the branch tracking through the flap's change point.
#include <mechanisms/four_bar/branch_tracker.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

namespace
{
  constexpr double eps = std::numeric_limits<double>::epsilon();

  // Independent reference: C is where the circle about B (radius l3) meets the circle about
  // D (radius l4). Returns both rocker angles.
  std::array<double, 2> rocker_angles_by_circles(const LinkLengths &l, const double th2)
  {
    const double          bx = l.crank * std::cos(th2), by = l.crank * std::sin(th2);
    const double          dx = l.ground - bx, dy = -by; // B -> D
    const double          d = std::hypot(dx, dy);
    const double          a = (l.coupler * l.coupler - l.rocker * l.rocker + d * d) / (2. * d);
    const double          h = std::sqrt(std::max(l.coupler * l.coupler - a * a, 0.));
    std::array<double, 2> angles;
    for (int side = 0; side < 2; ++side)
      {
        const double sign = side == 0 ? 1. : -1.;
        const double cx   = bx + a * dx / d - sign * h * dy / d;
        const double cy   = by + a * dy / d + sign * h * dx / d;
        angles[side]      = std::atan2(cy, cx - l.ground);
      }
    return angles;
  }

  double angle_difference(const double a, const double b)
  {
    return std::abs(wrap_angle(a - b));
  }
} // namespace

TEST(PositionAnalysis, FreudensteinRootsMatchCircleIntersection)
{
  for (const LinkLengths &l : {flap_linkage(), norton_crank_rocker()})
    for (double th2_deg = -179.; th2_deg <= 180.; th2_deg += 7.)
      {
        const auto roots     = rocker_angle_candidates(l, th2_deg * deg);
        const auto reference = rocker_angles_by_circles(l, th2_deg * deg);
        // The two sets agree as sets; tolerance: both are O(eps) computations of an angle,
        // amplified near the flap's fold where the roots are O(sqrt(eps)) sensitive.
        for (const double root : roots)
          EXPECT_LT(
            std::min(angle_difference(root, reference[0]), angle_difference(root, reference[1])),
            1e-10)
            << "crank " << th2_deg << " deg";
      }
}

TEST(PositionAnalysis, LoopClosesToRoundOffOverFullCrankRangeOnBothBranches)
{
  // Includes the fold th2 = 0 exactly (step divides 360).
  for (const LinkLengths &l : {flap_linkage(), norton_crank_rocker()})
    for (const AssemblyBranch branch : {AssemblyBranch::plus, AssemblyBranch::minus})
      for (double th2_deg = -360.; th2_deg <= 360.; th2_deg += 0.25)
        {
          const Pose pose = solve_pose(l, th2_deg * deg, branch);
          // A few rounding errors on lengths of size l_max.
          EXPECT_LT(closure_residual(l, pose), 16. * eps * l.longest())
            << "crank " << th2_deg << " deg, branch " << to_string(branch);
        }
}

TEST(PositionAnalysis, FlapFoldsIntoALineAtTheChangePoint)
{
  // At th2 = 0: B = (10, 0) mm and |BD| = 50 mm = l3 - l4, so C must be at (75, 0) mm on both
  // branches: the discriminant of Eq. E12 is zero there.
  const LinkLengths l     = flap_linkage();
  const auto        k     = freudenstein_coefficients(l, 0.);
  const double      scale = k.k1 * k.k1 + k.k2 * k.k2 + k.k3 * k.k3;
  EXPECT_LT(std::abs(k.discriminant), 1e-15 * scale);
  for (const AssemblyBranch branch : {AssemblyBranch::plus, AssemblyBranch::minus})
    {
      const auto joints = joint_positions(l, solve_pose(l, 0., branch));
      EXPECT_NEAR(joints.c[0], 0.075, 1e-15);
      EXPECT_NEAR(joints.c[1], 0., 1e-15);
    }
}

TEST(PositionAnalysis, BranchLabelsKeepTheirSideAwayFromTheFold)
{
  // Claim in position_analysis.h: minus puts C above AD, plus below, on the flap linkage.
  const LinkLengths l = flap_linkage();
  for (double th2_deg = 1.; th2_deg < 360.; th2_deg += 1.)
    {
      EXPECT_GT(joint_positions(l, solve_pose(l, th2_deg * deg, AssemblyBranch::minus)).c[1], 0.);
      EXPECT_LT(joint_positions(l, solve_pose(l, th2_deg * deg, AssemblyBranch::plus)).c[1], 0.);
    }
}

TEST(PositionAnalysis, TrackerPassesTheFoldWithContinuousSlope)
{
  // The smooth motion through the fold keeps dth4/dth2 continuous; the other root would turn
  // the rocker back with a slope jump from about -1.2 to +0.8. One-sided slopes of the tracked
  // path on both sides must agree to O(step).
  const LinkLengths l    = flap_linkage();
  const double      step = 0.01 * deg;
  BranchTracker     tracker(l, -2. * deg, AssemblyBranch::minus);
  std::vector<Pose> path{tracker.pose()};
  for (int i = 1; i <= 400; ++i)
    path.push_back(tracker.advance(-2. * deg + i * step)); // to +2 deg, th2 = 0 at i = 200
  const double slope_before = (path[200].rocker_angle - path[199].rocker_angle) / step;
  const double slope_after  = (path[201].rocker_angle - path[200].rocker_angle) / step;
  EXPECT_NEAR(slope_after, slope_before, 1e-2);
  EXPECT_LT(slope_before, -1.); // the rocker keeps moving the same way through the fold
  EXPECT_EQ(tracker.n_branch_switches(), 1u);
  // The continuation lands on the other root, C below the ground line.
  EXPECT_EQ(path.back().branch, AssemblyBranch::plus);
  EXPECT_LT(path.back().rocker_angle, 0.);
}

TEST(PositionAnalysis, ChangePointMotionRepeatsEveryTwoCrankTurns)
{
  // Through the fold the smooth motion changes branch, so after one crank turn the linkage is
  // on the other root of Eq. E13 (C below the ground line) and only after two turns back
  // where it started.
  const LinkLengths l     = flap_linkage();
  const double      start = 30. * deg, step = 0.5 * deg;
  BranchTracker     tracker(l, start, AssemblyBranch::minus);
  const Pose        initial = tracker.pose();
  Pose              after_one_turn{};
  for (int i = 1; i <= 1440; ++i)
    {
      const Pose &pose = tracker.advance(start + i * step);
      if (i == 720)
        after_one_turn = pose;
    }
  EXPECT_NEAR(wrap_angle(after_one_turn.rocker_angle -
                         solve_pose(l, start, AssemblyBranch::plus).rocker_angle),
              0., 1e-10);
  EXPECT_NEAR(wrap_angle(tracker.pose().rocker_angle - initial.rocker_angle), 0., 1e-10);
  EXPECT_EQ(tracker.n_branch_switches(), 2u);
}

TEST(PositionAnalysis, TrackerKeepsTheBranchOfANonSingularLinkage)
{
  const LinkLengths l = norton_crank_rocker();
  BranchTracker     tracker(l, 0., AssemblyBranch::plus);
  for (int i = 1; i <= 720; ++i)
    {
      const Pose &pose = tracker.advance(i * deg);
      EXPECT_LT(angle_difference(pose.rocker_angle,
                                 solve_pose(l, i * deg, AssemblyBranch::plus).rocker_angle),
                1e-12);
    }
  EXPECT_EQ(tracker.n_branch_switches(), 0u);
}

TEST(PositionAnalysis, ImpossibleCrankAngleThrowsDomainError)
{
  // Triple rocker (s + l = 10 > p + q = 9): the crank cannot reach th2 = pi.
  const LinkLengths l{7., 3., 4., 5.};
  EXPECT_THROW(solve_pose(l, M_PI, AssemblyBranch::plus), std::domain_error);
}

TEST(PositionAnalysis, BadLengthsThrowInvalidArgument)
{
  EXPECT_THROW(solve_pose({0.06, -0.01, 0.065, 0.015}, 0.3, AssemblyBranch::plus),
               std::invalid_argument);
  EXPECT_THROW(solve_pose({0.06, 0.01, std::nan(""), 0.015}, 0.3, AssemblyBranch::plus),
               std::invalid_argument);
  EXPECT_THROW(solve_pose(flap_linkage(), std::nan(""), AssemblyBranch::plus),
               std::invalid_argument);
}
