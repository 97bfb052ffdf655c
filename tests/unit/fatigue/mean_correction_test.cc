// Mean corrections against hand-evaluated formulas and their limiting cases.
#include <fatigue/mean_correction.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using fatigue::MeanCorrection;
using fatigue::MeanCorrectionSettings;

TEST(MeanCorrection, GoodmanHandValues)
{
  // 100 / (1 - 50 / 500) = 111.111...
  EXPECT_DOUBLE_EQ(fatigue::goodman_equivalent_amplitude(100.0, 50.0, 500.0), 1000.0 / 9.0);
  // Fully reversed: unchanged. Compressive mean: no credit.
  EXPECT_EQ(fatigue::goodman_equivalent_amplitude(100.0, 0.0, 500.0), 100.0);
  EXPECT_EQ(fatigue::goodman_equivalent_amplitude(100.0, -200.0, 500.0), 100.0);
  // Mean at the ultimate strength: static failure.
  EXPECT_TRUE(std::isinf(fatigue::goodman_equivalent_amplitude(1.0, 500.0, 500.0)));
}

TEST(MeanCorrection, SmithWatsonTopperLimits)
{
  // R = -1: sigma_max = sigma_a -> unchanged.
  EXPECT_DOUBLE_EQ(fatigue::smith_watson_topper_equivalent_amplitude(40.0, 0.0), 40.0);
  // R = 0: sigma_max = 2 sigma_a -> sqrt(2) sigma_a.
  EXPECT_DOUBLE_EQ(fatigue::smith_watson_topper_equivalent_amplitude(40.0, 40.0),
                   std::sqrt(2.0) * 40.0);
  // Entirely compressive cycle: no damage.
  EXPECT_EQ(fatigue::smith_watson_topper_equivalent_amplitude(10.0, -20.0), 0.0);
}

TEST(MeanCorrection, ElastomerWalkerHandValues)
{
  // R = 0: eps_eq = eps_a for any gamma.
  for (const double gamma : {0.0, 0.5, 1.0, 1.5})
    EXPECT_DOUBLE_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.08, 0.0, gamma), 0.04);
  // gamma = 1: amplitude only, mean strain has no effect (R = 0.5 here).
  EXPECT_DOUBLE_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.1, 0.05, 1.0), 0.025);
  // gamma = 0.5, R = 0.5: eps_a (1 - R)^(gamma - 1) = 0.025 * sqrt(2).
  EXPECT_DOUBLE_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.1, 0.05, 0.5),
                   0.025 * std::sqrt(2.0));
  // gamma = 0: only eps_max / 2 matters.
  EXPECT_DOUBLE_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.1, 0.05, 0.0), 0.05);
  // Compression is ignored: (0.05, -0.05) acts like (0.05, 0).
  EXPECT_DOUBLE_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.05, -0.05, 0.5), 0.025);
  // Never in tension, or static: no damage.
  EXPECT_EQ(fatigue::elastomer_equivalent_strain_amplitude(-0.01, -0.05, 0.5), 0.0);
  EXPECT_EQ(fatigue::elastomer_equivalent_strain_amplitude(0.05, 0.05, 0.5), 0.0);
}

TEST(MeanCorrection, HarmfulMeanStrainLowersLifeForGammaBelowOne)
{
  // Same amplitude 0.02, growing mean: equivalent amplitude grows for gamma < 1, falls for > 1.
  double previous_harmful = 0.0, previous_beneficial = std::numeric_limits<double>::infinity();
  for (const double mean : {0.02, 0.05, 0.1, 0.2})
    {
      const double harmful =
          fatigue::elastomer_equivalent_strain_amplitude(mean + 0.02, mean - 0.02, 0.5);
      const double beneficial =
          fatigue::elastomer_equivalent_strain_amplitude(mean + 0.02, mean - 0.02, 1.5);
      EXPECT_GT(harmful, previous_harmful);
      EXPECT_LT(beneficial, previous_beneficial);
      previous_harmful = harmful, previous_beneficial = beneficial;
    }
}

TEST(MeanCorrection, DispatchMatchesTheFormulas)
{
  MeanCorrectionSettings settings;
  EXPECT_EQ(fatigue::equivalent_amplitude(7.0, 1.0, settings), 3.0);
  settings.kind              = MeanCorrection::goodman;
  settings.ultimate_strength = 20.0;
  EXPECT_DOUBLE_EQ(fatigue::equivalent_amplitude(7.0, 1.0, settings), 3.0 / (1.0 - 4.0 / 20.0));
  settings.kind = MeanCorrection::smith_watson_topper;
  EXPECT_DOUBLE_EQ(fatigue::equivalent_amplitude(7.0, 1.0, settings), std::sqrt(7.0 * 3.0));
  settings.kind            = MeanCorrection::elastomer_walker;
  settings.walker_exponent = 0.5;
  EXPECT_DOUBLE_EQ(fatigue::equivalent_amplitude(0.07, 0.01, settings), std::sqrt(0.035 * 0.03));
}

TEST(MeanCorrection, NamesRoundTripAndBadInputThrows)
{
  for (const MeanCorrection kind :
       {MeanCorrection::none, MeanCorrection::goodman, MeanCorrection::smith_watson_topper,
        MeanCorrection::elastomer_walker})
    EXPECT_EQ(fatigue::parse_mean_correction(fatigue::to_string(kind)), kind);
  EXPECT_THROW(fatigue::parse_mean_correction("gerber"), std::invalid_argument);
  EXPECT_THROW(fatigue::goodman_equivalent_amplitude(1.0, 0.5, 0.0), std::invalid_argument);
  EXPECT_THROW(fatigue::goodman_equivalent_amplitude(-1.0, 0.5, 10.0), std::invalid_argument);
  EXPECT_THROW(fatigue::elastomer_equivalent_strain_amplitude(0.01, 0.02, 0.5),
               std::invalid_argument);
  EXPECT_THROW(fatigue::elastomer_equivalent_strain_amplitude(0.02, 0.01, -0.5),
               std::invalid_argument);
  MeanCorrectionSettings goodman_without_strength;
  goodman_without_strength.kind = MeanCorrection::goodman;
  try
    {
      goodman_without_strength.check();
      FAIL() << "Goodman without ultimate strength accepted";
    }
  catch (const std::invalid_argument &e)
    {
      EXPECT_NE(std::string(e.what()).find("ultimate_strength"), std::string::npos) << e.what();
    }
}
