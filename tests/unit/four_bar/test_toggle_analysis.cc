// Exact assembly and toggle analysis over a crank sweep, against brute force: the chain closed by
// the Freudenstein solution at 0.001 degree steps (an independent construction of C).
#include <mechanisms/four_bar/position_analysis.h>
#include <mechanisms/four_bar/toggle_analysis.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace compliant::four_bar;

namespace
{
  constexpr double deg = M_PI / 180;

  struct Sampled
  {
    double mu_min = M_PI, mu_max = 0, first_failure = -1; // travel where the chain first fails to close
  };

  // Transmission angle from the Freudenstein pose (|th4 - th3|), sampled along the sweep.
  Sampled sample(const LinkLengths &l, const double start, const double travel, const double step)
  {
    Sampled      s;
    const double sense = travel >= 0 ? 1 : -1;
    const int n = static_cast<int>(std::ceil(std::abs(travel) / step));
    for (int i = 0; i <= n; ++i) // the sweep's ends included
      try
        {
          const double t = std::abs(travel) * i / n;
          const Pose p = solve_pose(l, start + sense * t, AssemblyBranch::plus);
          const double mu = std::abs(wrap_angle(p.rocker_angle - p.coupler_angle));
          s.mu_min = std::min(s.mu_min, mu), s.mu_max = std::max(s.mu_max, mu);
        }
      catch (const std::domain_error &)
        {
          if (s.first_failure < 0)
            s.first_failure = std::abs(travel) * i / n;
        }
    return s;
  }
} // namespace

// A crank-rocker 0.05 degree of transmission angle from its toggle: the sweep through th2 = 0
// finds the closest approach exactly; the crank turns fully, so no toggle bounds it.
TEST(ToggleAnalysis, CrankRockerNearItsToggle)
{
  const double mu0 = 0.05 * deg, l3 = 0.9, l4 = 0.8;
  const double s0  = std::sqrt(l3 * l3 + l4 * l4 - 2 * l3 * l4 * std::cos(mu0));
  const LinkLengths l{0.3 + s0, 0.3, l3, l4};
  const auto sweep = analyse_crank_sweep(l, -0.4, 1.2);
  EXPECT_NEAR(sweep.mu_min, mu0, 1e-9);
  EXPECT_NEAR(sweep.transmission_margin, mu0, 1e-9);
  EXPECT_FALSE(sweep.toggle_inside);
  EXPECT_TRUE(sweep.closes_everywhere);
  EXPECT_EQ(sweep.crank_margin, std::numeric_limits<double>::infinity());
  const auto brute = sample(l, -0.4, 1.2, 0.001 * deg);
  EXPECT_LT(brute.first_failure, 0);
  EXPECT_NEAR(sweep.mu_max, brute.mu_max, 1e-6);
  EXPECT_GE(brute.mu_min, sweep.mu_min - 1e-12); // the sampled minimum cannot undercut the exact one
}

// A non-Grashof chain whose input is a rocker: the toggle angles bound its motion. Outside the
// sweep the margin is the rotation to the nearest one; a sweep across one reports where.
TEST(ToggleAnalysis, RockerInputMarginAndToggleInside)
{
  const LinkLengths l{1.0, 0.8, 0.5, 0.6}; // diagonal 0.2..1.8, closes for 0.1..1.1
  const auto        toggles = toggle_crank_angles(l);
  ASSERT_EQ(toggles.size(), 2u);
  const double limit = std::abs(toggles[0]);
  const auto   brute = sample(l, 0, M_PI, 0.001 * deg);
  EXPECT_NEAR(brute.first_failure, limit, 0.002 * deg);

  const auto inside_sweep = analyse_crank_sweep(l, -0.3, 0.6);
  EXPECT_FALSE(inside_sweep.toggle_inside);
  EXPECT_NEAR(inside_sweep.crank_margin, limit - 0.3, 1e-12);
  const auto brute_inside = sample(l, -0.3, 0.6, 0.001 * deg);
  EXPECT_NEAR(inside_sweep.mu_max, brute_inside.mu_max, 1e-6);
  EXPECT_NEAR(inside_sweep.mu_min, brute_inside.mu_min, 1e-6);

  const auto across = analyse_crank_sweep(l, 0.3, -2 * M_PI + 0.6); // the long way round, clockwise
  EXPECT_TRUE(across.toggle_inside);
  EXPECT_FALSE(across.closes_everywhere);
  EXPECT_NEAR(across.toggle_travel, 0.3 + limit, 1e-12);
  EXPECT_EQ(across.crank_margin, 0.);
}

// The assembly sign is the side of B -> D on which C lies, and assemble() builds it on either side.
TEST(ToggleAnalysis, AssemblySignsOfBothAssemblies)
{
  const LinkLengths l{1.0, 0.35, 0.9, 0.8};
  for (const double th2 : {-2.0, -0.5, 0.0, 0.7, 3.0})
    for (const int sign : {-1, 1})
      {
        const auto j = assemble(l, th2, sign);
        EXPECT_EQ(assembly_sign(j.b, j.c, j.d), sign);
        EXPECT_NEAR(std::hypot(j.c[0] - j.b[0], j.c[1] - j.b[1]), l.coupler, 1e-14);
        EXPECT_NEAR(std::hypot(j.c[0] - j.d[0], j.c[1] - j.d[1]), l.rocker, 1e-14);
      }
  EXPECT_THROW(assemble(LinkLengths{1.0, 0.8, 0.5, 0.6}, M_PI, 1), std::domain_error);
}
