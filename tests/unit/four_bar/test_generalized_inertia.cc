// Lagrangian terms: J(th2) against kinetic energy from finite-difference velocities of the mass
// centres, J' against finite differences of J, the gravity torque against finite differences of
// the potential, and a one-link pendulum in closed form.
#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/generalized_inertia.h>

#include <gtest/gtest.h>

#include <cmath>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

namespace
{
  // The paper's Table 1 masses and inertias, centres at mid-link.
  MovingLinkMasses flap_masses()
  {
    const LinkLengths l = flap_linkage();
    return {{3.154e-4, 1.11e-9, 0.5 * l.crank},
            {6.48e-5, 1.22e-9, 0.5 * l.coupler},
            {3.487e-5, 7.98e-9, 0.5 * l.rocker}};
  }

  Pose pose_near(const LinkLengths &l, const double th2, const Pose &near)
  {
    Pose p          = solve_pose(l, th2, near.branch);
    p.coupler_angle = near.coupler_angle + wrap_angle(p.coupler_angle - near.coupler_angle);
    p.rocker_angle  = near.rocker_angle + wrap_angle(p.rocker_angle - near.rocker_angle);
    return p;
  }
} // namespace

TEST(GeneralizedInertia, MatchesKineticEnergyFromFiniteDifferenceVelocities)
{
  // 2 E_kin / w2^2 with every velocity taken by central differences of positions and angles
  // (no velocity coefficients involved). Step 1e-6: relative error ~ 1e-12 + eps/1e-6.
  const LinkLengths      l          = flap_linkage();
  const MovingLinkMasses m          = flap_masses();
  const double           mass[3]    = {m.crank.mass, m.coupler.mass, m.rocker.mass};
  const double           inertia[3] = {m.crank.centre_inertia, m.coupler.centre_inertia,
                                       m.rocker.centre_inertia};
  for (double th2_deg = 10.; th2_deg < 360.; th2_deg += 25.)
    {
      const double th2  = th2_deg * deg;
      const Pose   pose = solve_pose(l, th2, AssemblyBranch::minus);
      const double step = 1e-6;
      const Pose   plus = pose_near(l, th2 + step, pose), minus = pose_near(l, th2 - step, pose);
      const auto   cp = mass_centres(l, m, plus), cm = mass_centres(l, m, minus);
      const double rate[3]   = {1., (plus.coupler_angle - minus.coupler_angle) / (2. * step),
                                (plus.rocker_angle - minus.rocker_angle) / (2. * step)};
      double       reference = 0.;
      for (unsigned int n = 0; n < 3; ++n)
        {
          const double vx = (cp[n][0] - cm[n][0]) / (2. * step);
          const double vy = (cp[n][1] - cm[n][1]) / (2. * step);
          reference += mass[n] * (vx * vx + vy * vy) + inertia[n] * rate[n] * rate[n];
        }
      const auto J = generalized_inertia(l, m, pose, derivative_coefficients(l, pose));
      EXPECT_NEAR(J.value, reference, 1e-8 * reference) << th2_deg;
    }
}

TEST(GeneralizedInertia, DerivativeMatchesFiniteDifferenceOfJ)
{
  const LinkLengths      l = flap_linkage();
  const MovingLinkMasses m = flap_masses();
  for (double th2_deg = 10.; th2_deg < 360.; th2_deg += 25.)
    {
      const double th2  = th2_deg * deg;
      const Pose   pose = solve_pose(l, th2, AssemblyBranch::minus);
      const auto   J_at = [&](const double angle) {
        const Pose p = pose_near(l, angle, pose);
        return generalized_inertia(l, m, p, derivative_coefficients(l, p)).value;
      };
      const double step = 1e-6;
      const double fd   = (J_at(th2 + step) - J_at(th2 - step)) / (2. * step);
      const auto   J    = generalized_inertia(l, m, pose, derivative_coefficients(l, pose));
      // Scale: J ~ 1e-8 kg m^2, so an absolute 1e-6 of J.
      EXPECT_NEAR(J.derivative, fd, 1e-6 * J.value) << th2_deg;
    }
}

TEST(GeneralizedInertia, GravityTorqueMatchesPotentialDerivative)
{
  const LinkLengths           l = flap_linkage();
  const MovingLinkMasses      m = flap_masses();
  const std::array<double, 2> g = {3.0, -9.0}; // oblique, to test both components
  for (double th2_deg = 10.; th2_deg < 360.; th2_deg += 25.)
    {
      const double th2  = th2_deg * deg;
      const Pose   pose = solve_pose(l, th2, AssemblyBranch::minus);
      const double step = 1e-6;
      const double fd   = (gravity_potential(l, m, pose_near(l, th2 + step, pose), g) -
                         gravity_potential(l, m, pose_near(l, th2 - step, pose), g)) /
                        (2. * step);
      EXPECT_NEAR(gravity_torque(l, m, pose, derivative_coefficients(l, pose), g), fd, 1e-12)
        << th2_deg;
    }
}

TEST(GeneralizedInertia, CrankAloneIsACompoundPendulum)
{
  // Only the crank has mass: J = I_c + m c^2, J' = 0, gravity torque m g c cos th2 (g along -y).
  const LinkLengths      l = flap_linkage();
  const MovingLinkMasses m{{2e-3, 3e-8, 0.004}, {0., 0., 0.03}, {0., 0., 0.007}};
  for (double th2_deg = 10.; th2_deg < 360.; th2_deg += 30.)
    {
      const Pose pose = solve_pose(l, th2_deg * deg, AssemblyBranch::plus);
      const auto h    = derivative_coefficients(l, pose);
      const auto J    = generalized_inertia(l, m, pose, h);
      EXPECT_NEAR(J.value, 3e-8 + 2e-3 * 0.004 * 0.004, 1e-22);
      EXPECT_NEAR(J.derivative, 0., 1e-22);
      EXPECT_NEAR(gravity_torque(l, m, pose, h, {0., -9.81}),
                  2e-3 * 9.81 * 0.004 * std::cos(th2_deg * deg), 1e-18);
    }
}

TEST(GeneralizedInertia, NegativeMassThrows)
{
  MovingLinkMasses m = flap_masses();
  m.coupler.mass     = -1.;
  EXPECT_THROW(check_masses(m), std::invalid_argument);
}
