// Palmgren-Miner damage: constant amplitude equals n / N, variable amplitude equals the hand sum,
// and the critical location is the hot spot with the largest damage.
#include <fatigue/hot_spot_assessment.h>
#include <fatigue/miner_damage.h>
#include <fatigue/printed_tpu.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace
{
  fatigue::LifeCurve
  curve(const double a_ref, const double k)
  {
    fatigue::LifeCurve c;
    c.name                = "test";
    c.reference_amplitude = a_ref;
    c.reference_cycles    = 1e6;
    c.exponent            = k;
    return c;
  }

  // A model whose three members are given curves, to test the bookkeeping independently of the
  // printed TPU assumption.
  fatigue::FatigueModel
  model_with(const fatigue::LifeCurve &low, const fatigue::LifeCurve &nominal,
             const fatigue::LifeCurve &high)
  {
    fatigue::FatigueModel model;
    model.name            = "test";
    model.quantity        = fatigue::Quantity::strain;
    model.correction.kind = fatigue::MeanCorrection::elastomer_walker;
    model.curves          = {low, nominal, high};
    return model;
  }

  // Surface strain of a flexure of thickness h and length l bent uniformly through theta (rad):
  // eps = h theta / (2 l) (pure bending, curvature theta / l).
  double
  bending_strain(const double theta_degrees)
  {
    const double h = 3.0, l = 10.0; // mm, the seed's flexure thickness and an assumed length
    return h * theta_degrees * M_PI / 180.0 / (2.0 * l);
  }

  // One sweep from rest to theta and back, sampled along a cosine (the rig's crank drive).
  void
  append_sweep(std::vector<double> &history, const double theta_degrees)
  {
    for (int i = 0; i < 16; ++i)
      history.push_back(bending_strain(theta_degrees) * 0.5 *
                        (1.0 - std::cos(2.0 * M_PI * i / 16.0)));
  }
} // namespace

TEST(MinerDamage, ConstantAmplitudeEqualsCountOverLife)
{
  // Five fully reversed periods of a sampled sine, amplitude 0.04, no mean correction.
  std::vector<double> history;
  for (int i = 0; i < 5 * 24; ++i)
    history.push_back(0.04 * std::sin(2.0 * M_PI * i / 24.0));
  const auto cycles   = fatigue::count_cycles(history, fatigue::HistoryKind::repeating);
  const auto spectrum = fatigue::equivalent_spectrum(cycles, fatigue::MeanCorrectionSettings{});
  const fatigue::LifeCurve c = curve(0.05, 6.0);
  const double             N = 1e6 * std::pow(0.04 / 0.05, -6.0);
  EXPECT_NEAR(fatigue::miner_damage(spectrum, c), 5.0 / N, 1e-12 * 5.0 / N);
  EXPECT_NEAR(fatigue::repeats_to_failure(fatigue::miner_damage(spectrum, c)), N / 5.0, 1e-9 * N);
}

TEST(MinerDamage, ConstantAmplitudeAtReferencePointIsExactlyOneOverNref)
{
  // R = 0 strain cycle 0 -> 0.1 -> 0: eps_eq = 0.05 = a_ref under the elastomer correction.
  const auto model  = model_with(curve(0.05, 4.0), curve(0.05, 6.0), curve(0.05, 8.0));
  const auto result = fatigue::assess_fatigue({{"flexure", {0.0, 0.05, 0.1, 0.05, 0.0}}}, model);
  for (std::size_t m = 0; m < fatigue::n_band_members; ++m)
    EXPECT_DOUBLE_EQ(result.hot_spots[0].damage_per_repeat[m], 1e-6);
}

// A duty cycle with three sweeps from rest, 26, 13 and 20 degrees: three R = 0 cycles of strain
// eps_i = h theta_i / (2 l), equivalent amplitudes eps_i / 2. Hand sum: D = sum (eps_i / 2 /
// a_ref)^k / N_ref.
TEST(MinerDamage, VariableAmplitudeDutyCycleEqualsHandSum)
{
  std::vector<double> history;
  for (const double theta : {26.0, 13.0, 20.0})
    append_sweep(history, theta);
  const fatigue::FatigueModel model  = fatigue::printed_tpu::strain_model();
  const auto                  result = fatigue::assess_fatigue({{"A", history}}, model);
  ASSERT_EQ(result.hot_spots[0].cycles.size(), 3u);
  for (std::size_t m = 0; m < fatigue::n_band_members; ++m)
    {
      const fatigue::LifeCurve &c    = model.curves[m];
      double                    hand = 0.0;
      for (const double theta : {26.0, 13.0, 20.0})
        hand += std::pow(0.5 * bending_strain(theta) / c.reference_amplitude, c.exponent) / 1e6;
      EXPECT_NEAR(result.hot_spots[0].damage_per_repeat[m], hand, 1e-12 * hand) << m;
      EXPECT_NEAR(result.hot_spots[0].repeats_to_failure[m], 1.0 / hand, 1e-9 / hand) << m;
    }
}

// Single-pass counting of the ASTM E1049-85 example, damage from the standard's table (half cycles
// at ranges 3, 6, 9; 1.5 at 4; 1 at 8), amplitude range / 2, no mean correction.
TEST(MinerDamage, AstmExampleHalfCyclesCountHalf)
{
  const auto cycles =
      fatigue::count_cycles({-2, 1, -3, 5, -1, 3, -4, 4, -2}, fatigue::HistoryKind::single_pass);
  const fatigue::LifeCurve c    = curve(2.0, 3.0);
  double                   hand = 0.0;
  for (const auto &[range, count] :
       std::vector<std::pair<double, double>>{{3, 0.5}, {4, 1.5}, {6, 0.5}, {8, 1.0}, {9, 0.5}})
    hand += count * std::pow(range / 2.0 / 2.0, 3.0) / 1e6;
  EXPECT_NEAR(fatigue::miner_damage(fatigue::equivalent_spectrum(cycles, {}), c), hand,
              1e-12 * hand);
}

TEST(HotSpots, CriticalLocationIsTheMostDamaged)
{
  std::vector<double> outer, inner;
  append_sweep(outer, 13.0);
  append_sweep(inner, 26.0);
  const fatigue::FatigueModel model = fatigue::printed_tpu::strain_model();
  const auto result = fatigue::assess_fatigue({{"outer", outer}, {"inner", inner}}, model);
  EXPECT_EQ(result.hot_spots[result.critical].name, "inner");
  EXPECT_TRUE(result.critical_location_is_robust());
  // Life band of the part = band of the critical hot spot; min/max over the members.
  const auto life = result.life();
  EXPECT_EQ(life.nominal, result.hot_spots[1].repeats_to_failure[fatigue::nominal_life]);
  EXPECT_EQ(life.low, result.hot_spots[1].repeats_to_failure[fatigue::low_life]);
  EXPECT_EQ(life.high, result.hot_spots[1].repeats_to_failure[fatigue::high_life]);
  EXPECT_LT(life.low, life.nominal);
  EXPECT_LT(life.nominal, life.high);
}

// One big cycle against twenty smaller ones: a shallow curve (k = 4) is dominated by the many small
// cycles, a steep one (k = 8) by the big one, so the members disagree on the critical location:
// k = 4: 1 * 0.10^4 = 1.0e-4 < 20 * 0.05^4 = 1.25e-4;  k = 8: 0.10^8 = 1e-8 > 20 * 0.05^8
// = 7.8e-10.
TEST(HotSpots, BandMembersCanDisagreeOnTheCriticalLocation)
{
  std::vector<double> big{0.0, 0.2}, many;
  for (int i = 0; i < 20; ++i)
    many.insert(many.end(), {0.0, 0.1});
  const auto model  = model_with(curve(0.05, 4.0), curve(0.05, 6.0), curve(0.05, 8.0));
  const auto result = fatigue::assess_fatigue({{"big", big}, {"many", many}}, model);
  EXPECT_EQ(result.critical_per_member[fatigue::low_life], 1u);
  EXPECT_EQ(result.critical_per_member[fatigue::high_life], 0u);
  EXPECT_FALSE(result.critical_location_is_robust());
}

TEST(HotSpots, BadInputThrows)
{
  const auto model = fatigue::printed_tpu::strain_model();
  EXPECT_THROW(fatigue::assess_fatigue({}, model), std::invalid_argument);
  EXPECT_THROW(fatigue::assess_fatigue({{"a", {0, 1}}, {"a", {0, 2}}}, model),
               std::invalid_argument);
  EXPECT_THROW(fatigue::assess_fatigue({{"", {0, 1}}}, model), std::invalid_argument);
  try
    {
      fatigue::assess_fatigue({{"hinge", {}}}, model);
      FAIL() << "empty history accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("hinge"), std::string::npos) << e.what();
    }
  EXPECT_THROW(fatigue::miner_damage({{0.01, -1.0}}, curve(0.05, 6.0)), std::invalid_argument);
  EXPECT_TRUE(std::isinf(fatigue::repeats_to_failure(0.0)));
}
