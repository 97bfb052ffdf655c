// Plate buckling against Timoshenko and Gere's table of k (Theory of Elastic Stability, 2nd ed.,
// table 9-2: simply supported plate under uniform compression, k = sigma_cr b^2 t / (pi^2 D),
// lowest over the half-waves m along the load, given to 3 significant digits).
#include <closed_forms/plates.h>
#include <closed_forms/registry.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
  double k_factor(double ratio, double m) // a/b = ratio, b = 1, t = 0.01
  {
    const double E = 1, nu = 0.3, t = 0.01;
    const double D = E * t * t * t / (12 * (1 - nu * nu));
    return closed_forms::plate_buckling_stress(ratio, 1, t, E, nu, m, 1) * t / (M_PI * M_PI * D);
  }
} // namespace

TEST(Plates, BucklingCoefficientsOfTimoshenkoAndGeresTable)
{
  const std::vector<std::pair<double, double>> table = {{0.2, 27.0}, {0.3, 13.2}, {0.4, 8.41}, {0.5, 6.25},
                                                        {0.6, 5.14}, {0.7, 4.53}, {0.8, 4.20}, {0.9, 4.04},
                                                        {1.0, 4.00}, {1.2, 4.13}, {1.4, 4.47}, {1.6, 4.20},
                                                        {1.8, 4.04}, {2.0, 4.00}, {2.5, 4.13}, {3.0, 4.00}};
  for (const auto &[ratio, k] : table)
    {
      double lowest = 1e300;
      for (int m = 1; m <= 5; ++m)
        lowest = std::min(lowest, k_factor(ratio, m));
      EXPECT_NEAR(lowest, k, 0.006 * k) << "a/b = " << ratio; // the table's 3 digits
    }
}

TEST(Plates, ModesAcrossTheLoadAndTheShearShare)
{
  // Square plate: (m + n^2/m)^2, so (1,1) 4, (3,1) 11.11, (1,3) 100, (3,3) 36.
  EXPECT_NEAR(k_factor(1, 3), 100.0 / 9, 1e-12);
  const double E = 1, nu = 0.3, t = 0.01;
  const double D = E * t * t * t / (12 * (1 - nu * nu));
  EXPECT_NEAR(closed_forms::plate_buckling_stress(1, 1, t, E, nu, 3, 3) * t / (M_PI * M_PI * D), 36, 1e-12);
  // Mindlin's share for the square plate's first mode: 2 (pi t / b)^2 / (6 kappa (1 - nu)).
  const double share = closed_forms::plate_buckling_shear_share(1, 1, t, E, nu, 1, 1);
  EXPECT_NEAR(share, 2 * std::pow(M_PI * t, 2) / (6 * (5.0 / 6.0) * (1 - nu)), 1e-15);
  // Registered: a thick plate warns, a thin one does not.
  const auto thin = closed_forms::evaluate("plate_buckling_stress", {{"a", 100}, {"b", 100}, {"t", 1}, {"E", 1},
                                                                     {"nu", 0.3}});
  EXPECT_NEAR(thin.value, 4 * M_PI * M_PI / (12 * 0.91) / 1e4, 1e-15);
  EXPECT_TRUE(thin.warnings.empty());
  const auto thick = closed_forms::evaluate("plate_buckling_stress", {{"a", 10}, {"b", 10}, {"t", 1}, {"E", 1},
                                                                      {"nu", 0.3}});
  EXPECT_EQ(thick.warnings.size(), 2u);
}

TEST(Plates, MindlinLowersTheKirchhoffStressByItsShearShare)
{
  const std::map<std::string, double> args = {{"a", 100}, {"b", 100}, {"t", 1}, {"E", 1000}, {"nu", 0.3}, {"m", 3}};
  const double kirchhoff = closed_forms::evaluate("plate_buckling_stress", args).value;
  const double mindlin   = closed_forms::evaluate("plate_buckling_stress_mindlin", args).value;
  const double share     = closed_forms::plate_buckling_shear_share(100, 100, 1, 1000, 0.3, 3, 1);
  EXPECT_NEAR(mindlin, kirchhoff / (1 + share), 1e-15 * kirchhoff);
  EXPECT_NEAR(share, 5 * closed_forms::plate_buckling_shear_share(100, 100, 1, 1000, 0.3, 1, 1), 1e-15);
  // Thin plates: shear vanishes like (t/b)^2.
  EXPECT_NEAR(closed_forms::plate_buckling_shear_share(100, 100, 0.5, 1000, 0.3, 1, 1) / share, 0.25 / 5, 1e-12);
}
