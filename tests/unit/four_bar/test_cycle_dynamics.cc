// Inverse dynamics over a cycle checked by the power balance T w2 = d/dt (E_kin + V_g + U), the
// motion law by finite differences, and the working-window search by direct position analysis.
#include <mechanisms/four_bar/cycle_dynamics.h>
#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/working_window.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "flap_linkage.h"

using namespace compliant::four_bar;
using namespace compliant::four_bar::testing;

namespace
{
  FlapMechanism flap_mechanism(const double K, const std::array<double, 2> &gravity,
                               const Pose &rest)
  {
    const LinkLengths l = flap_linkage();
    return {l,
            {{3.154e-4, 1.11e-9, 0.5 * l.crank},
             {6.48e-5, 1.22e-9, 0.5 * l.coupler},
             {3.487e-5, 7.98e-9, 0.5 * l.rocker}},
            {{K, K, K, K}, rest},
            gravity,
            AssemblyBranch::minus};
  }

  // max_j |T_j w2_j - dE/dt_j| / max_j |T_j w2_j| with dE/dt by central differences of the
  // sampled energies (samples equally spaced in time; the cycle is periodic).
  double power_balance_error(const std::vector<CycleSample> &cycle)
  {
    const std::size_t n     = cycle.size();
    const double      dt    = cycle[1].time - cycle[0].time;
    double            worst = 0., peak = 0.;
    for (std::size_t j = 0; j < n; ++j)
      {
        const auto  &next = cycle[(j + 1) % n], &prev = cycle[(j + n - 1) % n];
        const double e_next = next.kinetic_energy + next.gravity_energy + next.spring_energy;
        const double e_prev = prev.kinetic_energy + prev.gravity_energy + prev.spring_energy;
        const double power  = cycle[j].compliant_crank_torque() * cycle[j].crank.velocity;
        worst               = std::max(worst, std::abs(power - (e_next - e_prev) / (2. * dt)));
        peak                = std::max(peak, std::abs(power));
      }
    return worst / peak;
  }
} // namespace

TEST(CycleDynamics, HarmonicMotionLawMatchesFiniteDifferences)
{
  const MotionLaw law{MotionKind::harmonic_oscillation, 1.2, 0.8};
  const double    w = 2. * M_PI, dt = 1e-5;
  for (double t = 0.; t < 1.; t += 0.07)
    {
      const auto s  = law.at(w * t, w);
      const auto sp = law.at(w * (t + dt), w), sm = law.at(w * (t - dt), w);
      EXPECT_NEAR(s.velocity, (sp.angle - sm.angle) / (2. * dt), 1e-8);
      EXPECT_NEAR(s.acceleration, (sp.angle - 2. * s.angle + sm.angle) / (dt * dt), 1e-4);
      EXPECT_NEAR(s.velocity, s.drive_ratio * w, 1e-15);
    }
  EXPECT_NEAR(law.at(M_PI, w).angle - law.at(0., w).angle, 0.8, 1e-15); // the full sweep
}

TEST(CycleDynamics, PowerBalanceOfTheOscillatingFlap)
{
  // Inertia only (no springs, no gravity) tests J and J'; then the full compliant model.
  const LinkLengths l      = flap_linkage();
  const double      centre = crank_angle_with_right_transmission(l, AssemblyBranch::minus);
  const double    sweep = crank_sweep_for_rocker_sweep(l, AssemblyBranch::minus, centre, 26. * deg);
  const MotionLaw law{MotionKind::harmonic_oscillation, centre - 0.5 * sweep, sweep};
  const Pose      rest = solve_pose(l, centre - 0.5 * sweep, AssemblyBranch::minus);
  // 20000 samples: central-difference error ~ (w dt)^2 / 6 ~ 2e-8 of the power.
  const auto inertia_only =
    evaluate_cycle(flap_mechanism(0., {0., 0.}, rest), law, 2. * M_PI, 20000);
  EXPECT_LT(power_balance_error(inertia_only), 1e-6);
  const auto compliant =
    evaluate_cycle(flap_mechanism(0.3, {0., -9.81}, rest), law, 2. * M_PI, 20000);
  EXPECT_LT(power_balance_error(compliant), 1e-6);
}

TEST(CycleDynamics, PowerBalanceOfTheRigidFlapInFullRotationThroughTheFold)
{
  // Two crank turns at 60 rpm through the change point; the inertia terms stay finite and
  // consistent with the energy along the smooth (branch-switching) motion.
  const LinkLengths l = flap_linkage();
  const MotionLaw   law{MotionKind::full_rotation, 0., 0.};
  const auto        cycle =
    evaluate_cycle(flap_mechanism(0., {0., -9.81}, solve_pose(l, 0.1, AssemblyBranch::minus)), law,
                   2. * M_PI, 40000, 2);
  EXPECT_LT(power_balance_error(cycle), 1e-5);
}

TEST(CycleDynamics, ConstantSpeedPendulumCrank)
{
  // Only the crank has mass and turns at constant speed: no inertia torque, gravity torque
  // m g c cos th2.
  const LinkLengths   l = norton_crank_rocker();
  const FlapMechanism mechanism{l,
                                {{0.5, 0.01, 0.7}, {0., 0., 3.5}, {0., 0., 4.5}},
                                {{0., 0., 0., 0.}, solve_pose(l, 0., AssemblyBranch::plus)},
                                {0., -9.81},
                                AssemblyBranch::plus};
  const auto cycle = evaluate_cycle(mechanism, {MotionKind::full_rotation, 0., 0.}, 3., 360);
  for (const auto &s : cycle)
    {
      EXPECT_NEAR(s.inertia_torque, 0., 1e-14);
      EXPECT_NEAR(s.gravity_torque, 0.5 * 9.81 * 0.7 * std::cos(s.pose.crank_angle), 1e-13);
    }
}

TEST(CycleDynamics, TorqueStatisticsOfAKnownSignal)
{
  // Spring-only torque K (th2 - th20) under a harmonic law of a single grounded spring
  // (K2 = K3 = K4 = 0): T = K a (1 - cos phi), a = sweep/2: peak 2 K a, RMS K a sqrt(3/2).
  const LinkLengths   l = norton_crank_rocker();
  const double        K = 2., sweep = 0.6, a = 0.3;
  const MotionLaw     law{MotionKind::harmonic_oscillation, 0.5, sweep};
  const FlapMechanism mechanism{l,
                                {{0., 0., 0.}, {0., 0., 0.}, {0., 0., 0.}},
                                {{K, 0., 0., 0.}, solve_pose(l, 0.5, AssemblyBranch::plus)},
                                {0., 0.},
                                AssemblyBranch::plus};
  const auto          cycle = evaluate_cycle(mechanism, law, 2. * M_PI, 1000);
  const auto stats = torque_statistics(cycle, TorqueComponent::springs, TorqueReference::crank);
  EXPECT_NEAR(stats.peak, 2. * K * a, 1e-4); // sampling misses the exact peak by O(1/n^2)
  EXPECT_NEAR(stats.rms, K * a * std::sqrt(1.5), 1e-12);
}

TEST(WorkingWindow, CrankSweepGivesTheRequestedRockerSweep)
{
  const LinkLengths l = flap_linkage();
  for (const double centre_deg : {60., 128.7, 250.})
    for (const double target_deg : {10., 26., 40.})
      {
        const double centre = centre_deg * deg;
        const double sweep =
          crank_sweep_for_rocker_sweep(l, AssemblyBranch::minus, centre, target_deg * deg);
        // The rocker is monotone in these windows: the end poses give the sweep directly.
        const double th4_start =
          solve_pose(l, centre - 0.5 * sweep, AssemblyBranch::minus).rocker_angle;
        const double th4_end =
          solve_pose(l, centre + 0.5 * sweep, AssemblyBranch::minus).rocker_angle;
        EXPECT_NEAR(std::abs(th4_end - th4_start), target_deg * deg, 1e-9)
          << centre_deg << ", " << target_deg;
      }
}

TEST(WorkingWindow, AutomaticCentreHasARightTransmissionAngle)
{
  const LinkLengths l      = flap_linkage();
  const double      centre = crank_angle_with_right_transmission(l, AssemblyBranch::minus);
  EXPECT_NEAR(transmission_angle(solve_pose(l, centre, AssemblyBranch::minus)), 0.5 * M_PI, 1e-10);
  // Hand check: |BD|^2 = l3^2 + l4^2 at mu = 90 deg, so cos th2 = (l1^2 + l2^2 - l3^2 - l4^2) /
  // (2 l1 l2) = -0.625; the root with the larger |h4| is th2 = acos(-0.625) = 128.68 deg.
  EXPECT_NEAR(centre, std::acos(-0.625), 1e-10);
}

TEST(WorkingWindow, TheFoldIsDetectedInsideAWindow)
{
  const LinkLengths l = flap_linkage();
  EXPECT_LT(min_collinearity_over(l, AssemblyBranch::minus, -10. * deg, 10. * deg, 2000), 1e-3);
  EXPECT_GT(min_collinearity_over(l, AssemblyBranch::minus, 100. * deg, 150. * deg), 0.5);
}
