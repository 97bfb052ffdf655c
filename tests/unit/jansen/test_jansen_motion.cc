// Analytic velocity and acceleration analysis against finite differences of
// the position analysis (the independent reference).
#include <mechanisms/jansen/jansen_finite_differences.h>
#include <mechanisms/jansen/jansen_motion_analysis.h>
#include <mechanisms/jansen/jansen_position_analysis.h>
#include <mechanisms/jansen/jansen_turn_checks.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

using namespace compliant::jansen;

namespace
{
  constexpr double degree = M_PI / 180.;

  std::array<double, 6> as_array(const LinkRates &r)
  {
    return {r.link3, r.link4, r.link5, r.link6, r.link7, r.link8};
  }
} // namespace

// Link rates over a full turn at omega2 = 10 rad/s against fourth-order
// central differences with h = 1e-3 rad. Away from the swing the stencil error
// is ~1e-10 relative (truncation h^4 f^(6)/90, round-off 1e-16/h^2); in the
// swing near theta2 = 190 deg, where the dyad at G comes closest to a dead
// point, the high crank-angle derivatives raise the truncation to ~2e-7
// relative for the accelerations. Tolerances (relative to max(1, |value|)):
// 1e-8 for velocities, 2e-6 for accelerations; a 0.1 % error in any term of
// the analysis exceeds them by orders of magnitude.
TEST(JansenMotion, LinkRatesMatchFiniteDifferencesOverAFullTurn)
{
  const JansenLinkLengths l      = paper_link_lengths();
  const double            omega2 = 10.;
  const auto relative_gap = [](const double analytic, const double reference) {
    return std::abs(analytic - reference) / std::max(1., std::abs(analytic));
  };
  for (int i = 0; i < 360; i += 5)
    {
      const double       theta2 = i * degree;
      const JansenPose   pose   = solve_position(l, theta2);
      const JansenMotion m      = solve_motion(l, pose.angles, omega2);
      const auto         fd     = differentiate_position_analysis(l, theta2, omega2);
      const auto w = as_array(m.angular_velocities), w_fd = as_array(fd.angular_velocities);
      const auto a = as_array(m.angular_accelerations), a_fd = as_array(fd.angular_accelerations);
      for (std::size_t k = 0; k < 6; ++k)
        {
          EXPECT_LT(relative_gap(w[k], w_fd[k]), 1e-8) << "omega of link " << k + 3 << " at " << i << " deg";
          EXPECT_LT(relative_gap(a[k], a_fd[k]), 2e-6) << "alpha of link " << k + 3 << " at " << i << " deg";
        }
      const PlanarVector v = m.velocities[Joint::H], acc = m.accelerations[Joint::H];
      EXPECT_LT(norm(v - fd.foot_velocity) / std::max(1., norm(v)), 1e-8) << i << " deg";
      EXPECT_LT(norm(acc - fd.foot_acceleration) / std::max(1., norm(acc)), 2e-6) << i << " deg";
    }
}

// Every joint's velocity and acceleration, with a non-zero crank acceleration,
// against plain second-order central differences of the joint positions in
// time along theta2(t) = theta0 + omega2 t + alpha2 t^2 / 2 (written here, not
// taken from the library). Time steps: 1e-6 s for velocities (error ~1e-12
// relative), 2e-5 s for accelerations: truncation dt^2 x^(4) / 12 is ~1e-7 of
// |a| here (crank step 1.4e-4 rad, the fourth crank-angle derivative of a
// joint position up to ~100 times its second), round-off
// ~400 mm * 1e-16 / dt^2 = 1e-4 mm/s^2.
TEST(JansenMotion, JointVelocitiesAndAccelerationsMatchTimeDifferences)
{
  const JansenLinkLengths l      = paper_link_lengths();
  const double            omega2 = 7., alpha2 = -30.;
  for (const double theta0 : {0.3, 1.9, 3.3, 4.4, 5.85})
    {
      const auto positions_at = [&](const double t) {
        return joint_positions(l, theta0 + omega2 * t + 0.5 * alpha2 * t * t);
      };
      const JansenMotion m = solve_motion(l, solve_position(l, theta0).angles, omega2, alpha2);
      const double       dt_v = 1e-6, dt_a = 2e-5;
      const JointVectors p_vp = positions_at(dt_v), p_vm = positions_at(-dt_v);
      const JointVectors p_ap = positions_at(dt_a), p_a0 = positions_at(0.),
                         p_am = positions_at(-dt_a);
      for (const Joint j : all_joints)
        {
          const PlanarVector v_fd = (1. / (2. * dt_v)) * (p_vp[j] - p_vm[j]);
          const PlanarVector a_fd =
            (1. / (dt_a * dt_a)) * (p_ap[j] - 2. * p_a0[j] + p_am[j]);
          EXPECT_NEAR(m.velocities[j].x, v_fd.x, 1e-5) << joint_name(j);
          EXPECT_NEAR(m.velocities[j].y, v_fd.y, 1e-5) << joint_name(j);
          const double tolerance = 1e-3 + 1e-6 * norm(m.accelerations[j]);
          EXPECT_NEAR(m.accelerations[j].x, a_fd.x, tolerance) << joint_name(j);
          EXPECT_NEAR(m.accelerations[j].y, a_fd.y, tolerance) << joint_name(j);
        }
    }
}

// The velocity analysis is linear in omega2 and the acceleration analysis is
// alpha2 d theta/d theta2 + omega2^2 d^2 theta/d theta2^2: check both scalings
// against the unit-speed finite differences (round-off of the second
// difference ~1e-16 * 2 pi / h^2 ~ 1e-9, times omega2^2 = 16).
TEST(JansenMotion, RatesScaleWithCrankSpeedAndAcceleration)
{
  const JansenLinkLengths l      = paper_link_lengths();
  const double            theta2 = 2.2, omega2 = -4., alpha2 = 12.;
  const auto              unit   = differentiate_position_analysis(l, theta2, 1.);
  const JansenMotion m = solve_motion(l, solve_position(l, theta2).angles, omega2, alpha2);
  const auto first = as_array(unit.angular_velocities), second = as_array(unit.angular_accelerations);
  const auto w = as_array(m.angular_velocities), a = as_array(m.angular_accelerations);
  for (std::size_t k = 0; k < 6; ++k)
    {
      EXPECT_NEAR(w[k], omega2 * first[k], 1e-9);
      EXPECT_NEAR(a[k], alpha2 * first[k] + omega2 * omega2 * second[k], 1e-7);
    }
}

// The default branch never meets a dead point over the turn (the smallest
// dyad angle sine stays well away from zero), so the analysis is continuous
// and the loop Jacobian regular everywhere.
TEST(JansenMotion, NoDeadPointOverTheTurn)
{
  const TurnChecks checks = check_crank_turn(paper_link_lengths(), 3600);
  EXPECT_GT(checks.min_dyad_sine, 0.1);
  EXPECT_LT(checks.max_loop_residual, 1e-11);
  EXPECT_LT(checks.max_length_error, 1e-11);
}

TEST(JansenMotion, RejectsNonFiniteCrankSpeed)
{
  const JansenLinkLengths l = paper_link_lengths();
  const LinkAngles        a = solve_position(l, 1.).angles;
  EXPECT_THROW(solve_motion(l, a, std::nan("")), std::invalid_argument);
  EXPECT_THROW(solve_motion(l, a, 1., INFINITY), std::invalid_argument);
  EXPECT_THROW(differentiate_position_analysis(l, 1., 1., 0.), std::invalid_argument);
}
