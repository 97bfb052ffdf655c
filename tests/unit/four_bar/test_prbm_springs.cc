// PRBM springs: K = E I / l_k by hand, and the paper's Eq. 12 (virtual work) against the
// derivative of the total spring energy by central finite differences.
#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/prbm_springs.h>

#include <gtest/gtest.h>

#include <cmath>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

TEST(PrbmSprings, FlexuralPivotStiffnessByHand)
{
  // E b h^3 / (12 l) = 89.5e6 * 1.5e-3 * (3e-3)^3 / (12 * 1e-3) = 0.3020625 N m/rad.
  EXPECT_NEAR(flexural_pivot_stiffness(89.5e6, 1.5e-3, 3e-3, 1e-3), 0.3020625, 1e-15);
  // Inversely proportional to the flexure length.
  EXPECT_NEAR(flexural_pivot_stiffness(89.5e6, 1.5e-3, 3e-3, 4e-3), 0.3020625 / 4., 1e-15);
  EXPECT_THROW(flexural_pivot_stiffness(89.5e6, 1.5e-3, 3e-3, 0.), std::invalid_argument);
  EXPECT_THROW(flexural_pivot_stiffness(-1., 1.5e-3, 3e-3, 1e-3), std::invalid_argument);
}

TEST(PrbmSprings, MomentsVanishAtRestAndOpposeTheRotation)
{
  const LinkLengths l    = flap_linkage();
  const Pose        rest = solve_pose(l, 100. * deg, AssemblyBranch::minus);
  const PrbmSprings springs{{1., 2., 3., 4.}, rest};
  for (const double m : spring_moments(springs, rest))
    EXPECT_EQ(m, 0.);
  EXPECT_EQ(spring_energy(springs, rest), 0.);

  const Pose moved = solve_pose(l, 110. * deg, AssemblyBranch::minus);
  const auto r     = flexure_rotations(springs, moved);
  const auto m     = spring_moments(springs, moved);
  EXPECT_NEAR(r[0], 10. * deg, 1e-15);
  for (unsigned int i = 0; i < 4; ++i)
    EXPECT_EQ(m[i], -springs.stiffness[i] * r[i]);
}

TEST(PrbmSprings, VirtualWorkTorqueEqualsEnergyDerivative)
{
  // Eq. 12 must equal dU/dth2, U = sum K_i r_i^2 / 2 evaluated on exact poses. Unequal springs
  // so that every term of Eq. 12 is tested with its own weight. Central difference with step
  // 1e-6: truncation ~ 1e-12 |U'''|, round-off ~ eps U / 1e-6.
  const LinkLengths l = flap_linkage();
  for (const double rest_deg : {60., 105., 200., 300.})
    {
      const PrbmSprings springs{{0.3, 0.7, 1.1, 1.9},
                                solve_pose(l, rest_deg * deg, AssemblyBranch::minus)};
      for (double th2_deg = rest_deg - 40.; th2_deg <= rest_deg + 40.; th2_deg += 5.)
        {
          if (std::abs(std::remainder(th2_deg, 360.)) < 3.)
            continue; // keep off the fold, where the coefficients are undefined
          const double th2  = th2_deg * deg;
          const Pose   pose = solve_pose(l, th2, AssemblyBranch::minus);
          const double torque =
            input_torque_virtual_work(springs, pose, derivative_coefficients(l, pose));

          const double step      = 1e-6;
          const auto   energy_at = [&](const double angle) {
            Pose p          = solve_pose(l, angle, AssemblyBranch::minus);
            p.coupler_angle = pose.coupler_angle + wrap_angle(p.coupler_angle - pose.coupler_angle);
            p.rocker_angle = pose.rocker_angle + wrap_angle(p.rocker_angle - pose.rocker_angle);
            return spring_energy(springs, p);
          };
          const double derivative = (energy_at(th2 + step) - energy_at(th2 - step)) / (2. * step);
          EXPECT_NEAR(torque, derivative, 1e-7 * (1. + std::abs(derivative)))
            << "rest " << rest_deg << " deg, crank " << th2_deg << " deg";
        }
    }
}
