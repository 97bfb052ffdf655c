#include <mechanisms/burmester/dyad_synthesis.h>

#include <gtest/gtest.h>

#include "known_linkage.h"

using namespace compliant::burmester;

namespace
{
  // The paper's Table 3 (seed 001): trailing-spar point and orientation, unit chord.
  std::vector<PrecisionPosition> table3()
  {
    const double d = 3.14159265358979323846 / 180;
    return {{0.63747, 0.05847, 89.271 * d}, {0.67682, 0.08142, 86.917 * d},
            {0.71617, 0.10465, 84.319 * d}, {0.75519, 0.12381, 81.913 * d}};
  }
} // namespace

// Every dyad on the Burmester curves of Table 3 meets all three loop equations (Eq. 1) to
// round-off: residual below 1e-12 of the positions' size (0.1 chord) for dyads up to 10 chords.
TEST(DyadSynthesis, EveryDyadOfTable3SatisfiesItsLoopEquations)
{
  const auto positions = table3();
  const auto dyads     = burmester_curves(positions, 720);
  ASSERT_GT(dyads.size(), 100u);
  unsigned int checked = 0;
  for (const auto &d : dyads)
    if (std::abs(d.W) + std::abs(d.Z) < 10)
      {
        EXPECT_LT(dyad_residual(positions, d), 1e-12) << "beta2 " << d.beta2;
        ++checked;
      }
  EXPECT_GT(checked, 100u);
}

// Synthesis through four positions of a known crank-rocker finds its crank and rocker dyads: at the
// crank's own beta2 one dyad has the ground pivot A = (0, 0) and the moving pivot B_1; at the
// rocker's beta2, one has D = (1, 0) and C_1.
TEST(DyadSynthesis, RecoversTheDyadsOfAKnownFourBar)
{
  namespace kl = known_linkage;
  const auto positions = kl::positions();
  const double beta2_crank = kl::crank_angles[1] - kl::crank_angles[0];
  bool         found_crank = false;
  for (const auto &d : dyads_for_beta2(positions, beta2_crank))
    if (std::abs(d.centre_point - Complex(0, 0)) < 1e-10)
      {
        found_crank = true;
        EXPECT_LT(std::abs(d.circle_point - std::polar(kl::lengths.crank, kl::crank_angles[0])), 1e-10);
        for (unsigned int j = 1; j < 4; ++j)
          EXPECT_NEAR(std::remainder(d.beta[j] - (kl::crank_angles[j] - kl::crank_angles[0]), 2 * M_PI), 0, 1e-10);
      }
  EXPECT_TRUE(found_crank);

  const double rocker1 = kl::pose(kl::crank_angles[0]).rocker_angle;
  const double beta2_rocker = kl::pose(kl::crank_angles[1]).rocker_angle - rocker1;
  bool         found_rocker = false;
  for (const auto &d : dyads_for_beta2(positions, beta2_rocker))
    if (std::abs(d.centre_point - Complex(1, 0)) < 1e-10)
      {
        found_rocker = true;
        EXPECT_LT(std::abs(d.circle_point - (Complex(1, 0) + std::polar(kl::lengths.rocker, rocker1))), 1e-10);
      }
  EXPECT_TRUE(found_rocker);
}

TEST(DyadSynthesis, RefusesOtherThanFourPositions)
{
  auto positions = table3();
  positions.pop_back();
  EXPECT_THROW(compatibility_coefficients(positions), std::invalid_argument);
}
