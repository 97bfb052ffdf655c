// Velocity and acceleration coefficients against central finite differences of the position
// solution, and the transmission angle against the law of cosines.
#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <gtest/gtest.h>

#include <cmath>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

namespace
{
  // Angles of the branch-fixed solution; for the flap the window stays off the fold.
  std::array<double, 2> coupler_rocker(const LinkLengths &l, const double th2,
                                       const AssemblyBranch branch, const Pose &near)
  {
    const Pose p = solve_pose(l, th2, branch);
    return {near.coupler_angle + wrap_angle(p.coupler_angle - near.coupler_angle),
            near.rocker_angle + wrap_angle(p.rocker_angle - near.rocker_angle)};
  }
} // namespace

TEST(DerivativeCoefficients, MatchCentralDifferencesOverTheCrankRange)
{
  for (const LinkLengths &l : {flap_linkage(), norton_crank_rocker()})
    for (const AssemblyBranch branch : {AssemblyBranch::plus, AssemblyBranch::minus})
      for (double th2_deg = 2.; th2_deg <= 358.; th2_deg += 1.)
        {
          // Stay 2 deg away from the flap's fold at th2 = 0, where the coefficients are 0/0.
          const double th2  = th2_deg * deg;
          const Pose   pose = solve_pose(l, th2, branch);
          const auto   h    = derivative_coefficients(l, pose);
          ASSERT_FALSE(h.singular);

          // First derivative: step 1e-5, truncation ~ 1e-10 |th'''|, round-off ~ eps/1e-5 = 2e-11.
          const double d1 = 1e-5;
          const auto   p1 = coupler_rocker(l, th2 + d1, branch, pose);
          const auto   m1 = coupler_rocker(l, th2 - d1, branch, pose);
          EXPECT_NEAR(h.coupler_velocity, (p1[0] - m1[0]) / (2. * d1), 1e-7) << th2_deg;
          EXPECT_NEAR(h.rocker_velocity, (p1[1] - m1[1]) / (2. * d1), 1e-7) << th2_deg;

          // Second derivative: step 1e-4, truncation ~ 1e-9 |th''''|, round-off ~ 4 eps/1e-8
          // = 1e-7; the coefficients reach ~10 near the fold, hence the relative part.
          const double d2         = 1e-4;
          const auto   p2         = coupler_rocker(l, th2 + d2, branch, pose);
          const auto   m2         = coupler_rocker(l, th2 - d2, branch, pose);
          const double fd_coupler = (p2[0] - 2. * pose.coupler_angle + m2[0]) / (d2 * d2);
          const double fd_rocker  = (p2[1] - 2. * pose.rocker_angle + m2[1]) / (d2 * d2);
          EXPECT_NEAR(h.coupler_acceleration, fd_coupler, 1e-5 * (1. + std::abs(fd_coupler)))
            << th2_deg;
          EXPECT_NEAR(h.rocker_acceleration, fd_rocker, 1e-5 * (1. + std::abs(fd_rocker)))
            << th2_deg;
        }
}

TEST(DerivativeCoefficients, MatchThePapersEquationsE17E18)
{
  // E17/E18 with the appendix naming (crank l1, coupler l2, rocker l3, angles th, alpha, phi):
  // S1 = l1 sin(phi - th) / (l2 sin(alpha - phi)), S2 = l1 sin(alpha - th) / (l3 sin(alpha - phi)).
  const LinkLengths l = flap_linkage();
  for (double th2_deg = 5.; th2_deg < 360.; th2_deg += 10.)
    {
      const Pose   p  = solve_pose(l, th2_deg * deg, AssemblyBranch::minus);
      const double s1 = l.crank * std::sin(p.rocker_angle - p.crank_angle) /
                        (l.coupler * std::sin(p.coupler_angle - p.rocker_angle));
      const double s2 = l.crank * std::sin(p.coupler_angle - p.crank_angle) /
                        (l.rocker * std::sin(p.coupler_angle - p.rocker_angle));
      const auto h = derivative_coefficients(l, p);
      EXPECT_NEAR(h.coupler_velocity, s1, 1e-13 * (1. + std::abs(s1)));
      EXPECT_NEAR(h.rocker_velocity, s2, 1e-13 * (1. + std::abs(s2)));
    }
}

TEST(DerivativeCoefficients, SingularAtTheFold)
{
  const auto h =
    derivative_coefficients(flap_linkage(), solve_pose(flap_linkage(), 0., AssemblyBranch::plus));
  EXPECT_TRUE(h.singular);
  EXPECT_TRUE(std::isnan(h.rocker_velocity));
}

TEST(DerivativeCoefficients, TransmissionAngleObeysTheLawOfCosines)
{
  // |BD|^2 = l3^2 + l4^2 - 2 l3 l4 cos(mu) (triangle BCD).
  for (const LinkLengths &l : {flap_linkage(), norton_crank_rocker()})
    for (double th2_deg = 3.; th2_deg < 360.; th2_deg += 9.)
      {
        const Pose   p  = solve_pose(l, th2_deg * deg, AssemblyBranch::minus);
        const auto   j  = joint_positions(l, p);
        const double bd = std::hypot(j.d[0] - j.b[0], j.d[1] - j.b[1]);
        const double cos_mu =
          (l.coupler * l.coupler + l.rocker * l.rocker - bd * bd) / (2. * l.coupler * l.rocker);
        EXPECT_NEAR(std::cos(transmission_angle(p)), cos_mu, 1e-12);
        EXPECT_GE(transmission_angle(p), 0.);
        EXPECT_LE(transmission_angle(p), M_PI);
      }
}
