// Saint-Venant and Vlasov torsion of a solid rectangle against published tables, thin-strip limits
// and an independent finite-volume solve of the warping problem.
#include <closed_forms/beams.h>
#include <closed_forms/torsion.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "warping_finite_differences.h"

using namespace closed_forms;

namespace
{
  // Classical three-figure tables: beta from Timoshenko and Goodier, Theory of Elasticity, sec. 109
  // (1 .. 4, 10) and the widely copied extension with a/b = 6 (Shigley, Mechanical Engineering
  // Design, table 3-1); alpha from the same sources.
  constexpr std::array<double, 7> aspect_ratios{1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 10.0};
  constexpr std::array<double, 7> published_beta{0.141, 0.196, 0.229, 0.263, 0.281, 0.299, 0.313};
  constexpr std::array<double, 7> published_alpha{0.208, 0.231, 0.246, 0.267, 0.282, 0.299, 0.312};
  // Half a unit of the third figure, except where the published figure is not the rounded series:
  // beta(6) = 0.29832 and alpha(6) = 0.29836 (published 0.299), beta(10) = 0.31233 (0.313 in
  // closed-forms.md and seed C; Timoshenko and Goodier print 0.312). The series values are confirmed
  // to 1e-5 by the finite-volume test below, so those three entries are 0.0007 high in print.
  constexpr std::array<double, 7> beta_tolerance{5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 1e-3, 1e-3};
  constexpr std::array<double, 7> alpha_tolerance{5e-4, 5e-4, 5e-4, 5e-4, 5e-4, 1e-3, 5e-4};

  constexpr double E = 200e3;  // MPa, spring steel (seed C)
  constexpr double nu = 0.3;
} // namespace

TEST(SaintVenant, BetaMatchesClassicalTable)
{
  for (std::size_t i = 0; i < aspect_ratios.size(); ++i)
    EXPECT_NEAR(saint_venant_beta(aspect_ratios[i], 1.0), published_beta[i], beta_tolerance[i])
      << "a/b = " << aspect_ratios[i];
  // The rounded series at the two disputed entries.
  EXPECT_NEAR(saint_venant_beta(6.0, 1.0), 0.298, 5e-4);
  EXPECT_NEAR(saint_venant_beta(10.0, 1.0), 0.312, 5e-4);
}

TEST(SaintVenant, AlphaMatchesClassicalTable)
{
  for (std::size_t i = 0; i < aspect_ratios.size(); ++i)
    EXPECT_NEAR(saint_venant_alpha(aspect_ratios[i], 1.0), published_alpha[i], alpha_tolerance[i])
      << "a/b = " << aspect_ratios[i];
  EXPECT_NEAR(saint_venant_alpha(6.0, 1.0), 0.298, 5e-4);
}

TEST(SaintVenant, SidesAreAcceptedInEitherOrder)
{
  EXPECT_DOUBLE_EQ(saint_venant_beta(3.0, 7.0), saint_venant_beta(7.0, 3.0));
  EXPECT_DOUBLE_EQ(torsion_constant(3.0, 7.0), torsion_constant(7.0, 3.0));
  EXPECT_DOUBLE_EQ(warping_constant(3.0, 7.0), warping_constant(7.0, 3.0));
  EXPECT_DOUBLE_EQ(saint_venant_max_shear_stress(5.0, 3.0, 7.0),
                   saint_venant_max_shear_stress(5.0, 7.0, 3.0));
}

// Thin strip: beta -> 1/3 - 0.21 b/a (Roark, table 10.1 case 4; the end correction is exponentially
// small in a/b), alpha -> beta, Gamma -> a^3 b^3/144 (omega -> -x y away from the short ends).
TEST(SaintVenant, ThinStripLimits)
{
  for (const double ratio : {10.0, 20.0, 100.0, 1000.0})
    {
      const double beta = saint_venant_beta(ratio, 1.0);
      // 0.21 is 0.2101 rounded: allow that rounding times b/a.
      EXPECT_NEAR(beta, 1.0 / 3.0 - 0.21 / ratio, 2e-4 / ratio) << "a/b = " << ratio;
      EXPECT_NEAR(saint_venant_alpha(ratio, 1.0), beta, 1e-6) << "a/b = " << ratio;
      // omega = -x y misses a correction of relative order (b/a)^2 near the short ends.
      const double thin_gamma = ratio * ratio * ratio / 144.0;
      EXPECT_NEAR(warping_constant(ratio, 1.0) / thin_gamma, 1.0, 5.0 / (ratio * ratio))
        << "a/b = " << ratio;
    }
  EXPECT_NEAR(saint_venant_beta(1e6, 1.0), 1.0 / 3.0, 1e-6);
}

// closed-forms.md (series; matches the sectionproperties package), given to 7 figures.
TEST(SaintVenant, TorsionAndWarpingConstantsOf100By50)
{
  EXPECT_NEAR(torsion_constant(100.0, 50.0) / 2.858521e6, 1.0, 2e-7);
  EXPECT_NEAR(warping_constant(100.0, 50.0) / 3.175417e8, 1.0, 2e-7);
}

// Finite-volume solution of the warping problem on two grids (h and h/2), Richardson-extrapolated.
// The measured extrapolation error is 1e-6 .. 1e-5 for these shapes; 1e-4 leaves a margin.
TEST(SaintVenant, SeriesAgreeWithFiniteVolumeWarpingSolve)
{
  for (const auto &[a, b] : std::vector<std::pair<double, double>>{{2.0, 1.0}, {1.0, 1.0}})
    {
      const unsigned int n = 40;
      const unsigned int nx = static_cast<unsigned int>(n * a / b);
      const auto coarse = closed_forms_tests::solve_warping_by_finite_volumes(a, b, nx, n);
      const auto fine = closed_forms_tests::solve_warping_by_finite_volumes(a, b, 2 * nx, 2 * n);
      const double gamma = (4.0 * fine.warping_constant - coarse.warping_constant) / 3.0;
      const double J = (4.0 * fine.torsion_constant - coarse.torsion_constant) / 3.0;
      EXPECT_NEAR(warping_constant(a, b) / gamma, 1.0, 1e-4) << a << " x " << b;
      EXPECT_NEAR(torsion_constant(a, b) / J, 1.0, 1e-4) << a << " x " << b;

      // Pointwise on the fine grid: second-order error, measured 1.6e-5 of a b/4.
      double max_difference = 0.0;
      for (unsigned int j = 0; j < fine.ny; j += 3)
        for (unsigned int i = 0; i < fine.nx; i += 5)
          max_difference =
            std::max(max_difference, std::abs(fine.omega[i + fine.nx * j] -
                                              warping_function(a, b, fine.x(i), fine.y(j))));
      EXPECT_LT(max_difference, 1e-4 * a * b / 4.0) << a << " x " << b;
    }
}

// The disputed table entries (a/b = 6 and 10) by the finite-volume solve: coarse grids suffice for
// thin sections (measured Richardson error 2e-5 with 20 and 40 cells across the thickness).
TEST(SaintVenant, BetaOfSlenderSectionsByFiniteVolumes)
{
  for (const double ratio : {6.0, 10.0})
    {
      const unsigned int n = 20;
      const unsigned int nx = static_cast<unsigned int>(n * ratio);
      const auto coarse = closed_forms_tests::solve_warping_by_finite_volumes(ratio, 1.0, nx, n);
      const auto fine = closed_forms_tests::solve_warping_by_finite_volumes(ratio, 1.0, 2 * nx, 2 * n);
      const double beta = (4.0 * fine.torsion_constant - coarse.torsion_constant) / 3.0 / ratio;
      EXPECT_NEAR(saint_venant_beta(ratio, 1.0), beta, 1e-4 * beta) << "a/b = " << ratio;
    }
}

// A bar with a < b is the same bar turned by 90 degrees: (x, y) -> (y, -x).
TEST(SaintVenant, WarpingFunctionOfTurnedSection)
{
  for (const auto &[x, y] : std::vector<std::pair<double, double>>{{0.3, 0.7}, {-0.2, 0.9}})
    EXPECT_NEAR(warping_function(1.0, 2.0, x, y), warping_function(2.0, 1.0, y, -x), 1e-14);
  EXPECT_THROW(warping_function(2.0, 1.0, 1.2, 0.0), std::invalid_argument);
}

TEST(SaintVenant, StiffnessIsShearModulusTimesTorsionConstantOverLength)
{
  const double G = E / (2.0 * (1.0 + nu));
  EXPECT_NEAR(saint_venant_torsion_stiffness(3.0, 0.5, 5.0, E, nu),
              G * torsion_constant(3.0, 0.5) / 5.0, 1e-12 * G);
  // tau_max of a thin strip tends to 3 T/(a b^2) (Roark, table 10.1 case 4, a/b -> infinity).
  // The 0.21 b/a correction of beta is 0.06 % at a/b = 1000.
  EXPECT_NEAR(saint_venant_max_shear_stress(1.0, 1000.0, 1.0) / (3.0 / 1000.0), 1.0, 1e-3);
}

namespace
{
  // Independent solution of Vlasov's equation E Gamma phi'''' - G J phi'' = 0 on [0, L],
  // phi(0) = phi'(0) = 0, phi(L) = 1, phi'(L) = 0, by RK4 shooting on the unknown phi''(0), phi'''(0)
  // (linear: two shots and a 2x2 solve). Returns the torque T = G J phi' - E Gamma phi''' for unit twist.
  double
  vlasov_stiffness_by_shooting(const double GJ, const double EGamma, const double L)
  {
    const double lambda2 = GJ / EGamma;
    const unsigned int steps = 4000;
    const double ds = L / steps;
    const auto shoot = [&](const double second, const double third) {
      std::array<double, 4> y{0.0, 0.0, second, third};  // phi, phi', phi'', phi'''
      const auto f = [&](const std::array<double, 4> &u) {
        return std::array<double, 4>{u[1], u[2], u[3], lambda2 * u[2]};
      };
      for (unsigned int k = 0; k < steps; ++k)
        {
          const auto k1 = f(y);
          std::array<double, 4> t;
          for (int c = 0; c < 4; ++c)
            t[c] = y[c] + 0.5 * ds * k1[c];
          const auto k2 = f(t);
          for (int c = 0; c < 4; ++c)
            t[c] = y[c] + 0.5 * ds * k2[c];
          const auto k3 = f(t);
          for (int c = 0; c < 4; ++c)
            t[c] = y[c] + ds * k3[c];
          const auto k4 = f(t);
          for (int c = 0; c < 4; ++c)
            y[c] += ds / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        }
      return y;
    };
    const auto u = shoot(1.0, 0.0), w = shoot(0.0, 1.0);
    // c1 u + c2 w: phi(L) = 1, phi'(L) = 0.
    const double det = u[0] * w[1] - w[0] * u[1];
    const double c2 = (u[0] * 0.0 - 1.0 * u[1]) / det;
    // At s = 0: phi' = 0, phi''' = c2.
    return -EGamma * c2;
  }
} // namespace

TEST(Vlasov, AgreesWithShootingSolutionOfTheDifferentialEquation)
{
  const double a = 4.0, b = 0.5;  // a leaf of seed C
  const double GJ = E / (2.0 * (1.0 + nu)) * torsion_constant(a, b);
  const double EGamma = E * warping_constant(a, b);
  // Shooting loses about exp(lambda L) * 1e-16 (lambda L = 21 at L = 20).
  for (const double L : {0.5, 2.0, 4.0, 10.0, 20.0})
    EXPECT_NEAR(vlasov_torsion_stiffness(a, b, L, E, nu) /
                  vlasov_stiffness_by_shooting(GJ, EGamma, L),
                1.0, 1e-7)
      << "L = " << L;
}

// closed-forms.md: within 5 % of Saint-Venant only for L >~ 10 a; several times stiffer for L ~ a.
TEST(Vlasov, TendsToSaintVenantForLongBarsAndIsMuchStifferForShortOnes)
{
  const double a = 10.0, b = 0.5;  // thin strip, 1/lambda ~ 0.23 a
  const auto ratio = [&](const double L) {
    return vlasov_torsion_stiffness(a, b, L, E, nu) / saint_venant_torsion_stiffness(a, b, L, E, nu);
  };
  EXPECT_GT(ratio(10.0 * a), 1.0);
  EXPECT_LT(ratio(10.0 * a), 1.05);
  EXPECT_LT(ratio(1000.0 * a), 1.0005);
  EXPECT_GT(ratio(5.0 * a), 1.05);
  EXPECT_GT(ratio(a), 1.5);
  EXPECT_GT(ratio(0.5 * a), 3.0);
  // Decreasing towards 1 with length.
  EXPECT_GT(ratio(2.0 * a), ratio(3.0 * a));
}

// For L -> 0 warping alone carries the torque: E Gamma phi'''' = 0 clamped-clamped gives
// 12 E Gamma / L^3 (the fixed-guided beam with E I -> E Gamma), next term (2/5)(lambda L/2)^2.
TEST(Vlasov, ShortBarLimitIsPureWarpingStiffness)
{
  const double a = 3.0, b = 1.0;
  const double G = E / (2.0 * (1.0 + nu));
  const double lambda = std::sqrt(G * torsion_constant(a, b) / (E * warping_constant(a, b)));
  for (const double L : {1e-4, 1e-3, 1e-2})
    {
      const double x = 0.5 * lambda * L;
      const double limit = 12.0 * E * warping_constant(a, b) / (L * L * L);
      EXPECT_NEAR(vlasov_torsion_stiffness(a, b, L, E, nu) / limit, 1.0 + 0.4 * x * x, 1e-3 * x * x)
        << "L = " << L;
    }
  // The series and the closed form meet without a jump at lambda L / 2 = 0.02.
  const double L_switch = 0.04 / lambda;
  EXPECT_NEAR(vlasov_torsion_stiffness(a, b, L_switch * (1.0 - 1e-9), E, nu) /
                vlasov_torsion_stiffness(a, b, L_switch * (1.0 + 1e-9), E, nu),
              1.0, 1e-8);
}

TEST(Torsion, BadInputThrowsNamingTheParameter)
{
  try
    {
      torsion_constant(-1.0, 2.0);
      FAIL() << "no exception";
    }
  catch (const std::invalid_argument &error)
    {
      EXPECT_NE(std::string(error.what()).find("'a'"), std::string::npos) << error.what();
    }
  EXPECT_THROW(saint_venant_torsion_stiffness(1.0, 2.0, 0.0, E, nu), std::invalid_argument);
  EXPECT_THROW(vlasov_torsion_stiffness(1.0, 2.0, 1.0, E, 0.5), std::invalid_argument);
}
