#include <mechanisms/burmester/candidate_mechanism.h>

#include <gtest/gtest.h>

#include "known_linkage.h"

using namespace compliant::burmester;
namespace kl = known_linkage;

namespace
{
  // The crank and rocker dyads of the known linkage, from synthesis.
  std::pair<Dyad, Dyad> known_dyads(const std::vector<PrecisionPosition> &positions,
                                    const std::array<double, 4>           &cranks)
  {
    Dyad crank{}, rocker{};
    for (const auto &d : dyads_for_beta2(positions, cranks[1] - cranks[0]))
      if (std::abs(d.centre_point) < 1e-9)
        crank = d;
    const double beta2 = kl::pose(cranks[1]).rocker_angle - kl::pose(cranks[0]).rocker_angle;
    for (const auto &d : dyads_for_beta2(positions, beta2))
      if (std::abs(d.centre_point - Complex(1, 0)) < 1e-9)
        rocker = d;
    return {crank, rocker};
  }
} // namespace

// Driven by its crank, the recovered mechanism passes the four positions in order, on one branch,
// with coupler point and orientation errors at round-off (the motion is tracked in 0.5 degree steps
// by the four-bar library's branch tracker).
TEST(CandidateMechanism, RecoveredFourBarPassesEveryPositionInOrder)
{
  const auto positions       = kl::positions();
  const auto [crank, rocker] = known_dyads(positions, kl::crank_angles);
  const auto m               = analyse_candidate(positions, crank, rocker);
  EXPECT_TRUE(m.defect_free) << m.defect;
  EXPECT_LT(m.position_error, 1e-10);
  EXPECT_LT(m.angle_error, 1e-10);
  EXPECT_NEAR(m.lengths.ground, kl::lengths.ground, 1e-10);
  EXPECT_NEAR(m.lengths.crank, kl::lengths.crank, 1e-10);
  EXPECT_NEAR(m.lengths.coupler, kl::lengths.coupler, 1e-10);
  EXPECT_NEAR(m.lengths.rocker, kl::lengths.rocker, 1e-10);
  EXPECT_NEAR(m.input_sweep, kl::crank_angles[3] - kl::crank_angles[0], 1e-10);
  EXPECT_EQ(m.grashof.class_, compliant::four_bar::GrashofClass::crank_rocker);
  // The transmission angle over the motion includes the values at the positions.
  EXPECT_LE(m.mu_min, m.mu_min_at_positions);
  EXPECT_GE(m.mu_max, m.mu_max_at_positions);
}

// The same linkage asked for the positions in the order 1, 3, 2, 4: the crank meets them out of
// order, which the check must call an order defect.
TEST(CandidateMechanism, DetectsAnOrderDefect)
{
  const std::array<double, 4> cranks{kl::crank_angles[0], kl::crank_angles[2], kl::crank_angles[1],
                                     kl::crank_angles[3]};
  const auto positions       = kl::positions(cranks);
  const auto [crank, rocker] = known_dyads(positions, cranks);
  const auto m               = analyse_candidate(positions, crank, rocker);
  EXPECT_FALSE(m.defect_free);
  EXPECT_NE(m.defect.find("order"), std::string::npos) << m.defect;
}

// Positions taken on the two assembly branches of one linkage: the mechanism reaches position 4
// only on the other branch, a branch (or circuit) defect.
TEST(CandidateMechanism, DetectsABranchDefect)
{
  auto positions = kl::positions();
  const auto other = compliant::four_bar::solve_pose(kl::lengths, kl::crank_angles[3],
                                                     compliant::four_bar::AssemblyBranch::plus);
  const Complex r = std::polar(kl::lengths.crank, kl::crank_angles[3]) +
                    kl::offset * std::polar(1.0, other.coupler_angle);
  positions[3] = {r.real(), r.imag(), other.coupler_angle};
  const auto [crank, rocker] = known_dyads(positions, kl::crank_angles);
  ASSERT_LT(std::abs(crank.centre_point), 1e-9);
  const auto m = analyse_candidate(positions, crank, rocker);
  EXPECT_FALSE(m.defect_free);
  EXPECT_TRUE(m.defect.find("branch") != std::string::npos || m.defect.find("circuit") != std::string::npos)
    << m.defect;
}
