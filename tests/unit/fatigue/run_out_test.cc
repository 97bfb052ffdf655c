// Run-out implications against the closed-form bound a_ref >= a_t (n_s / N_ref)^(1/k).
#include <fatigue/printed_tpu.h>
#include <fatigue/run_out.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
  fatigue::LifeCurve
  curve(const double a_ref, const double k, const double endurance = 0.0)
  {
    fatigue::LifeCurve c;
    c.name                = "test";
    c.reference_amplitude = a_ref;
    c.reference_cycles    = 1e6;
    c.exponent            = k;
    c.endurance_amplitude = endurance;
    return c;
  }

  constexpr double seed_run_out = 717727.0; // cycles survived by the seed paper's flap, no failure
} // namespace

TEST(RunOut, ContradictedCurveIsLiftedToTheClosedFormBound)
{
  // a_t = 0.068 (e.g. a 5 mm flexure, 3 mm thick, bent 26 deg from rest: 3 * 0.4538 / (2 * 5) / 2).
  const fatigue::LifeCurve c = curve(0.05, 6.0);
  const auto               r = fatigue::implied_by_run_out(c, 0.068, seed_run_out);
  EXPECT_DOUBLE_EQ(r.predicted, 1e6 * std::pow(0.068 / 0.05, -6.0)); // 158,000: before the run-out
  EXPECT_FALSE(r.consistent);
  ASSERT_TRUE(r.lower_bound.has_value());
  const double bound = 0.068 * std::pow(seed_run_out / 1e6, 1.0 / 6.0);
  EXPECT_NEAR(r.lower_bound->reference_amplitude, bound, 1e-15);
  EXPECT_NEAR(r.minimum_scale, bound / 0.05, 1e-14);
  // The lower-bound curve passes through the run-out point ...
  EXPECT_NEAR(r.lower_bound->cycles_to_failure(0.068), seed_run_out, 1e-8 * seed_run_out);
  // ... and is what the constrained curve becomes.
  EXPECT_DOUBLE_EQ(r.constrained().reference_amplitude, bound);
  // Amplitude that survives 1e6 cycles by the bound: a_t (n_s / 1e6)^(1/k).
  EXPECT_NEAR(r.lower_bound->amplitude_at(1e6), 0.068 * std::pow(seed_run_out / 1e6, 1.0 / 6.0),
              1e-15);
}

TEST(RunOut, ConsistentCurveIsKept)
{
  const fatigue::LifeCurve c = curve(0.05, 6.0);
  const auto               r = fatigue::implied_by_run_out(c, 0.034, seed_run_out);
  EXPECT_TRUE(r.consistent);
  EXPECT_LT(r.minimum_scale, 1.0);
  EXPECT_DOUBLE_EQ(r.constrained().reference_amplitude, 0.05);
}

// A duty cycle at two hot spots: both survived n_s repeats, so the more damaged one sets the bound.
TEST(RunOut, MostDamagedHotSpotSetsTheBound)
{
  const fatigue::LifeCurve       c = curve(0.05, 4.0);
  const fatigue::LoadingSpectrum mild{{0.02, 1.0}};
  const fatigue::LoadingSpectrum severe{{0.04, 1.0}, {0.03, 2.0}};
  const auto                     r = fatigue::implied_by_run_out(c, {mild, severe}, seed_run_out);
  // D(s) = s^-k D(1) with D(1) = (0.04^4 + 2 * 0.03^4) / (0.05^4 * 1e6).
  const double damage = (std::pow(0.04, 4) + 2.0 * std::pow(0.03, 4)) / (std::pow(0.05, 4) * 1e6);
  EXPECT_NEAR(r.minimum_scale, std::pow(seed_run_out * damage, 0.25), 1e-14);
  EXPECT_NEAR(r.predicted, 1.0 / damage, 1e-9 / damage);
}

// With an endurance amplitude the bound is found by bisection; where the endurance amplitude stays
// below every cycle it must agree with the closed form, and in general n D(s*) = 1 at the infimum.
TEST(RunOut, EnduranceLimitBisection)
{
  const fatigue::LoadingSpectrum spectrum{{0.06, 1.0}, {0.05, 3.0}};
  const auto closed = fatigue::implied_by_run_out(curve(0.05, 6.0), {spectrum}, seed_run_out);
  const auto bisected =
      fatigue::implied_by_run_out(curve(0.05, 6.0, 1e-4), {spectrum}, seed_run_out);
  EXPECT_NEAR(bisected.minimum_scale, closed.minimum_scale, 1e-12 * closed.minimum_scale);

  // Endurance 0.045: for s >= 0.05 / 0.045 = 1.111 the 0.05 cycles stop counting, and the root of
  // n D(s) = 1 is then continuous, s* = 1.2 (n_s / 1e6)^(1/6) = 1.1354 from the 0.06 cycle alone.
  const fatigue::LifeCurve c = curve(0.05, 6.0, 0.045);
  const auto               r = fatigue::implied_by_run_out(c, {spectrum}, seed_run_out);
  EXPECT_NEAR(r.minimum_scale, 1.2 * std::pow(seed_run_out / 1e6, 1.0 / 6.0), 1e-12);
  auto n_damage = [&](const fatigue::LifeCurve &curve_, const double s) {
    return seed_run_out * fatigue::miner_damage(spectrum, curve_.scaled(s, "s"));
  };
  EXPECT_LE(n_damage(c, r.minimum_scale), 1.0 + 1e-12);
  EXPECT_GT(n_damage(c, r.minimum_scale * (1.0 - 1e-9)), 1.0);

  // Endurance 0.042: the jump at s = 0.05 / 0.042 = 1.1905 lies between the two power-law roots
  // (1.1354 and 1.2752), so n D jumps from above 1 to below 1 there: s* is the jump itself.
  const fatigue::LifeCurve jump = curve(0.05, 6.0, 0.042);
  const auto               j    = fatigue::implied_by_run_out(jump, {spectrum}, seed_run_out);
  EXPECT_NEAR(j.minimum_scale, 0.05 / 0.042, 1e-12);
  EXPECT_GT(n_damage(jump, j.minimum_scale * (1.0 - 1e-9)), 1.0);
}

TEST(RunOut, HarmlessLoadingGivesNoBound)
{
  const auto r = fatigue::implied_by_run_out(curve(0.05, 6.0), {{{0.0, 1.0}}}, seed_run_out);
  EXPECT_TRUE(r.consistent);
  EXPECT_EQ(r.minimum_scale, 0.0);
  EXPECT_FALSE(r.lower_bound.has_value());
}

TEST(RunOut, ModelBandIsCheckedMemberByMember)
{
  const fatigue::FatigueModel model = fatigue::printed_tpu::strain_model();
  // One R = 0 cycle of eps_a = 0.034 per duty cycle.
  const std::vector<fatigue::LoadingSpectrum> spectra{{{0.034, 1.0}}};
  const auto implications = fatigue::check_against_run_out(model, spectra, seed_run_out);
  for (std::size_t m = 0; m < fatigue::n_band_members; ++m)
    EXPECT_EQ(implications[m].consistent, model.curves[m].cycles_to_failure(0.034) >= seed_run_out)
        << m;
  const fatigue::FatigueModel constrained = fatigue::constrained_by_run_out(model, implications);
  for (std::size_t m = 0; m < fatigue::n_band_members; ++m)
    EXPECT_GE(constrained.curves[m].cycles_to_failure(0.034), seed_run_out * (1.0 - 1e-12)) << m;
}

TEST(RunOut, BadInputThrows)
{
  EXPECT_THROW(fatigue::implied_by_run_out(curve(0.05, 6.0), 0.03, 0.0), std::invalid_argument);
  EXPECT_THROW(fatigue::implied_by_run_out(curve(0.05, 6.0), 0.0, 1e5), std::invalid_argument);
  EXPECT_THROW(fatigue::implied_by_run_out(curve(0.05, 6.0), {}, 1e5), std::invalid_argument);
}
