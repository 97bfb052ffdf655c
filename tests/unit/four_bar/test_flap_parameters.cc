// Parameter handling of flap_prbm: defaults from the paper, clear errors for bad input.
#include <mechanisms/four_bar/flap_parameters.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace compliant::four_bar;

namespace
{
  // Message of the std::invalid_argument thrown by action, or "" if none.
  template <typename Action> std::string invalid_argument_message(Action action)
  {
    try
      {
        action();
      }
    catch (const std::invalid_argument &error)
      {
        return error.what();
      }
    return "";
  }
} // namespace

TEST(FlapParameters, DefaultsAreThePapersTable1InSI)
{
  const FlapParameters p = FlapParameterSet().parameters();
  EXPECT_DOUBLE_EQ(p.lengths.ground, 0.060);
  EXPECT_DOUBLE_EQ(p.lengths.crank, 0.010);
  EXPECT_DOUBLE_EQ(p.lengths.coupler, 0.065);
  EXPECT_DOUBLE_EQ(p.lengths.rocker, 0.015);
  EXPECT_DOUBLE_EQ(p.masses.crank.mass, 3.154e-4);
  EXPECT_DOUBLE_EQ(p.masses.rocker.centre_inertia, 7.98e-9);
  EXPECT_DOUBLE_EQ(p.masses.coupler.centre_offset, 0.0325);
  EXPECT_DOUBLE_EQ(p.youngs_modulus, 89.5e6);
  EXPECT_NEAR(p.sweep, 26. * M_PI / 180., 1e-15);
  EXPECT_NEAR(p.motor_speed, 2. * M_PI, 1e-15);
  EXPECT_NEAR(p.gravity[1], -9.81, 1e-12);
  EXPECT_TRUE(p.automatic_centre);
}

TEST(FlapParameters, OverridesAndErrorsNameTheParameter)
{
  FlapParameterSet set;
  set.set("flexure_length_mm = 2.5");
  EXPECT_DOUBLE_EQ(set.parameters().flexure_length, 2.5e-3);

  EXPECT_NE(
    invalid_argument_message([&] { set.set("flexure_lenght_mm=2"); }).find("flexure_lenght_mm"),
    std::string::npos);
  set.set("youngs_modulus_mpa=-3");
  EXPECT_NE(invalid_argument_message([&] { set.parameters(); }).find("youngs_modulus_mpa"),
            std::string::npos);
  set.set("youngs_modulus_mpa=89.5");
  set.set("sweep_link=flap");
  EXPECT_NE(invalid_argument_message([&] { set.parameters(); }).find("sweep_link"),
            std::string::npos);
  EXPECT_FALSE(invalid_argument_message([&] { set.set("no equals sign"); }).empty());
}

TEST(FlapParameters, FileErrorsNameFileAndLine)
{
  const std::string file = ::testing::TempDir() + "flap_parameters_test.prm";
  {
    std::ofstream out(file);
    out << "# comment\nsweep_deg = 20\n\nnot a pair\n";
  }
  FlapParameterSet  set;
  const std::string message = invalid_argument_message([&] { set.read_file(file); });
  EXPECT_NE(message.find(file + ":4"), std::string::npos) << message;
  std::remove(file.c_str());
  EXPECT_FALSE(invalid_argument_message([&] { set.read_file("/nonexistent/x.prm"); }).empty());
}
