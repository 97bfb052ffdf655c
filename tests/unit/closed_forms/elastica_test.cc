// Large-deflection cantilever: published table, perturbation expansion, an independent RK4 shooting
// solution of the elastica, and elliptic-integral identities.
#include <closed_forms/elastica.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace closed_forms;

namespace
{
  // Independent solution: RK4 on theta' = kappa_0 - alpha x, x' = cos theta, y' = sin theta
  // (s in [0, 1]; the first equation is the moment balance M(s) = P (x_tip - x(s))), shooting on the
  // root curvature kappa_0 until theta'(1) = kappa_0 - alpha x(1) = 0, by bisection on [0, alpha].
  CantileverTip
  shoot(const double alpha)
  {
    const unsigned int steps = 4000;
    const double ds = 1.0 / steps;
    const auto integrate = [&](const double kappa_0) {
      std::array<double, 3> u{0.0, 0.0, 0.0};  // theta, x, y
      const auto f = [&](const std::array<double, 3> &v) {
        return std::array<double, 3>{kappa_0 - alpha * v[1], std::cos(v[0]), std::sin(v[0])};
      };
      for (unsigned int k = 0; k < steps; ++k)
        {
          const auto k1 = f(u);
          std::array<double, 3> t;
          for (int c = 0; c < 3; ++c)
            t[c] = u[c] + 0.5 * ds * k1[c];
          const auto k2 = f(t);
          for (int c = 0; c < 3; ++c)
            t[c] = u[c] + 0.5 * ds * k2[c];
          const auto k3 = f(t);
          for (int c = 0; c < 3; ++c)
            t[c] = u[c] + ds * k3[c];
          const auto k4 = f(t);
          for (int c = 0; c < 3; ++c)
            u[c] += ds / 6.0 * (k1[c] + 2.0 * k2[c] + 2.0 * k3[c] + k4[c]);
        }
      return u;
    };
    double lower = 0.0, upper = alpha;
    for (int iteration = 0; iteration < 60; ++iteration)
      {
        const double middle = 0.5 * (lower + upper);
        (middle - alpha * integrate(middle)[1] < 0.0 ? lower : upper) = middle;
      }
    const auto u = integrate(0.5 * (lower + upper));
    return {u[0], u[2], 1.0 - u[1]};
  }
} // namespace

// closed-forms.md table (Bisshopp and Drucker 1945, recomputed), five decimals.
TEST(TipLoadElastica, MatchesPublishedTable)
{
  const double alpha[] = {0.5, 1.0, 2.0};
  const double rotation[] = {0.24453, 0.46135, 0.78175};
  const double deflection[] = {0.16214, 0.30172, 0.49346};
  const double shortening[] = {0.01592, 0.05643, 0.16064};
  for (int i = 0; i < 3; ++i)
    {
      const CantileverTip tip = tip_load_elastica(alpha[i]);
      EXPECT_NEAR(tip.rotation, rotation[i], 1e-5) << "alpha = " << alpha[i];
      EXPECT_NEAR(tip.deflection, deflection[i], 1e-5) << "alpha = " << alpha[i];
      EXPECT_NEAR(tip.shortening, shortening[i], 1e-5) << "alpha = " << alpha[i];
    }
}

// RK4 with 4000 steps is accurate to ~1e-12 here; the bisection to 2^-60 alpha.
TEST(TipLoadElastica, AgreesWithShootingSolution)
{
  for (const double alpha : {0.3, 3.0, 10.0, 30.0})
    {
      const CantileverTip exact = tip_load_elastica(alpha);
      const CantileverTip shot = shoot(alpha);
      EXPECT_NEAR(exact.rotation, shot.rotation, 1e-9) << "alpha = " << alpha;
      EXPECT_NEAR(exact.deflection, shot.deflection, 1e-9) << "alpha = " << alpha;
      EXPECT_NEAR(exact.shortening, shot.shortening, 1e-9) << "alpha = " << alpha;
    }
}

// Regular perturbation of theta'' = -alpha cos theta in alpha (derived for this test):
// theta = alpha (s - s^2/2) + alpha^3 theta_3, giving v/L = alpha/3 - 4 alpha^3/105,
// tip rotation alpha/2 - 11 alpha^3/240 and shortening alpha^2/15, each up to O(alpha^2) relative.
// The first terms are the linear results P L^3/(3 E I) and P L^2/(2 E I).
TEST(TipLoadElastica, SmallLoadLimit)
{
  for (const double alpha : {1e-6, 1e-3, 0.05})
    {
      const CantileverTip tip = tip_load_elastica(alpha);
      const double a3 = alpha * alpha * alpha, a5 = a3 * alpha * alpha;
      EXPECT_NEAR(tip.deflection, alpha / 3.0 - 4.0 * a3 / 105.0, a5 + 1e-15) << alpha;
      EXPECT_NEAR(tip.rotation, alpha / 2.0 - 11.0 * a3 / 240.0, a5 + 1e-15) << alpha;
      EXPECT_NEAR(tip.shortening, alpha * alpha / 15.0, a3 * alpha + 1e-15) << alpha;
    }
}

// For large loads the beam hangs along the load except for a boundary layer of length
// L/sqrt(alpha) at the clamp: with m -> 1 (E(m) -> 1, E(phi_1, 1) = sin phi_1 = 1/sqrt 2) the
// deflection tends to 1 - (2 - sqrt 2)/sqrt(alpha), the shortening to 1 - sqrt(2/alpha), and the
// rotation to 90 deg: K(m) ~ ln(4/k'), F(pi/4, 1) = ln(1 + sqrt 2) give 90 deg - theta_0 ~ 2 k' =
// 8 exp(-sqrt(alpha)) / (1 + sqrt 2), below rounding beyond alpha ~ 1e3.
TEST(TipLoadElastica, LargeLoadsAndSymmetry)
{
  double previous = 0.0;
  for (const double alpha : {10.0, 100.0, 1e3, 1e4, 1e5})
    {
      const CantileverTip tip = tip_load_elastica(alpha);
      EXPECT_GE(tip.rotation, previous);
      EXPECT_LE(tip.rotation, 0.5 * M_PI);
      previous = tip.rotation;
      if (alpha >= 1e3)
        {
          EXPECT_NEAR(tip.deflection, 1.0 - (2.0 - std::sqrt(2.0)) / std::sqrt(alpha), 1e-12) << alpha;
          EXPECT_NEAR(tip.shortening, 1.0 - std::sqrt(2.0 / alpha), 1e-12) << alpha;
        }
    }
  EXPECT_NEAR(0.5 * M_PI - tip_load_elastica(100.0).rotation,
              8.0 * std::exp(-10.0) / (1.0 + std::sqrt(2.0)), 1e-8);
  EXPECT_THROW(tip_load_elastica(2e5), std::invalid_argument);
  // A reversed load mirrors the shape.
  const CantileverTip up = tip_load_elastica(1.5), down = tip_load_elastica(-1.5);
  EXPECT_DOUBLE_EQ(down.rotation, -up.rotation);
  EXPECT_DOUBLE_EQ(down.deflection, -up.deflection);
  EXPECT_DOUBLE_EQ(down.shortening, up.shortening);
}

// Uniform curvature t/L: geometry of circular arcs.
TEST(EndMomentElastica, CircularArcGeometry)
{
  const CantileverTip half = end_moment_elastica(M_PI);  // semicircle of diameter 2L/pi
  EXPECT_NEAR(half.deflection, 2.0 / M_PI, 1e-15);
  EXPECT_NEAR(half.shortening, 1.0, 1e-15);
  const CantileverTip full = end_moment_elastica(2.0 * M_PI);  // closes into a full circle
  EXPECT_NEAR(full.deflection, 0.0, 1e-15);
  EXPECT_NEAR(full.shortening, 1.0, 1e-15);
  EXPECT_DOUBLE_EQ(full.rotation, 2.0 * M_PI);
  // Linear limit: v = M L^2 / (2 E I), i.e. v/L = t/2; shortening t^2/6 (chord of a shallow arc).
  // Next terms: relative -t^2/12 and -t^2/20; both sides of the series switch at t = 0.1.
  for (const double t : {1e-8, 1e-5, 1e-2, 0.1 * (1.0 - 1e-12), 0.1 * (1.0 + 1e-12)})
    {
      const CantileverTip tip = end_moment_elastica(t);
      EXPECT_NEAR(tip.deflection / (t / 2.0), 1.0 - t * t / 12.0, t * t * t * t / 100.0 + 1e-14) << t;
      EXPECT_NEAR(tip.shortening / (t * t / 6.0), 1.0 - t * t / 20.0, t * t * t * t / 100.0 + 1e-12)
        << t;
    }
  EXPECT_EQ(end_moment_elastica(0.0).deflection, 0.0);
  const CantileverTip negative = end_moment_elastica(-1.0);
  EXPECT_DOUBLE_EQ(negative.deflection, -end_moment_elastica(1.0).deflection);
  EXPECT_DOUBLE_EQ(negative.shortening, end_moment_elastica(1.0).shortening);
}

// Abramowitz and Stegun table 17.1 (m = 1/2) and DLMF identities.
TEST(EllipticIntegrals, PublishedValuesAndIdentities)
{
  EXPECT_NEAR(elliptic_f(0.5 * M_PI, 0.5), 1.8540746773013719, 1e-15);
  EXPECT_NEAR(elliptic_e(0.5 * M_PI, 0.5), 1.3506438810476755, 1e-15);
  // Legendre's relation E K' + E' K - K K' = pi/2 (DLMF 19.7.1).
  for (const double m : {0.1, 0.3, 0.7, 0.9, 0.999})
    {
      const double K = elliptic_f(0.5 * M_PI, m), E = elliptic_e(0.5 * M_PI, m);
      const double Kc = elliptic_f(0.5 * M_PI, 1.0 - m), Ec = elliptic_e(0.5 * M_PI, 1.0 - m);
      EXPECT_NEAR(E * Kc + Ec * K - K * Kc, 0.5 * M_PI, 1e-14) << "m = " << m;
    }
  // Degenerate parameters (DLMF 19.6.7, 19.6.8): m = 0 gives phi, m = 1 gives atanh(sin), sin.
  for (const double phi : {0.1, 0.7, 1.3})
    {
      EXPECT_NEAR(elliptic_f(phi, 0.0), phi, 1e-15);
      EXPECT_NEAR(elliptic_e(phi, 0.0), phi, 1e-15);
      EXPECT_NEAR(elliptic_f(phi, 1.0), std::atanh(std::sin(phi)), 1e-14);
      EXPECT_NEAR(elliptic_e(phi, 1.0), std::sin(phi), 1e-15);
    }
}
