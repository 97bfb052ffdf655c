// Linear beam formulas against the unit-load method, structural symmetry and published roots.
#include <closed_forms/beams.h>
#include <closed_forms/registry.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace closed_forms;

namespace
{
  // Seed A flexure section (mm) in a generic stiff polymer (MPa); values are arbitrary but typical.
  constexpr double b = 1.5, h = 3.0, E = 2000.0, nu = 0.35, P = 1.0;

  // Unit-load (virtual work) deflection of a tip-loaded cantilever, by Simpson's rule on
  // int M m / (E I) dx + int V v / (kappa G A) dx, M = P (L - x), m = L - x, V = P, v = 1.
  double
  unit_load_deflection(const double L, const double EI, const double kGA)
  {
    const unsigned int intervals = 100;
    const double dx = L / intervals;
    double sum = 0.0;
    for (unsigned int k = 0; k <= intervals; ++k)
      {
        const double x = k * dx;
        const double weight = (k == 0 || k == intervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
        sum += weight * (P * (L - x) * (L - x) / EI + P / kGA);
      }
    return sum * dx / 3.0;
  }
} // namespace

TEST(Beams, SectionProperties)
{
  EXPECT_DOUBLE_EQ(second_moment_of_area(2.0, 3.0), 4.5);  // 2 * 27 / 12
  EXPECT_DOUBLE_EQ(section_area(2.0, 3.0), 6.0);
  EXPECT_DOUBLE_EQ(shear_modulus(260.0, 0.3), 100.0);
}

// Simpson's rule is exact for the quadratic integrand: agreement to rounding.
TEST(Beams, CantileverDeflectionsMatchTheUnitLoadMethod)
{
  const double L = 20.0;
  const double EI = E * b * h * h * h / 12.0;
  const double kGA = 5.0 / 6.0 * E / (2.0 * (1.0 + nu)) * b * h;
  EXPECT_NEAR(euler_bernoulli_cantilever_deflection(P, L, E, b, h) /
                unit_load_deflection(L, EI, 1e300),
              1.0, 1e-12);
  EXPECT_NEAR(timoshenko_cantilever_deflection(P, L, E, nu, b, h) / unit_load_deflection(L, EI, kGA),
              1.0, 1e-12);
}

// The shear share is 3 E I/(kappa G A L^2) = (E/(4 kappa G)) (h/L)^2: it vanishes for slender beams.
TEST(Beams, TimoshenkoTendsToEulerBernoulliForSlenderBeams)
{
  const double shear_coefficient = E / (4.0 * 5.0 / 6.0 * E / (2.0 * (1.0 + nu)));
  for (const double slenderness : {3.0, 10.0, 100.0, 1000.0})
    {
      const double L = slenderness * h;
      const double ratio = timoshenko_cantilever_deflection(P, L, E, nu, b, h) /
                           euler_bernoulli_cantilever_deflection(P, L, E, b, h);
      EXPECT_NEAR(ratio - 1.0, shear_coefficient / (slenderness * slenderness), 1e-12);
      const double guided_ratio = euler_bernoulli_guided_stiffness(L, E, b, h) /
                                  timoshenko_guided_stiffness(L, E, nu, b, h);
      EXPECT_NEAR(guided_ratio - 1.0, 4.0 * shear_coefficient / (slenderness * slenderness), 1e-12);
    }
  EXPECT_NEAR(timoshenko_guided_stiffness(1000.0 * h, E, nu, b, h) /
                euler_bernoulli_guided_stiffness(1000.0 * h, E, b, h),
              1.0, 1e-5);
}

// Antisymmetry: a fixed-guided beam has its inflection point at mid-span, so it is two cantilevers of
// length L/2 in series carrying the same shear force.
TEST(Beams, GuidedBeamIsTwoHalfCantileversInSeries)
{
  for (const double L : {6.0, 30.0, 300.0})
    {
      EXPECT_NEAR(euler_bernoulli_guided_stiffness(L, E, b, h) *
                    (2.0 * euler_bernoulli_cantilever_deflection(1.0, 0.5 * L, E, b, h)),
                  1.0, 1e-12);
      EXPECT_NEAR(timoshenko_guided_stiffness(L, E, nu, b, h) *
                    (2.0 * timoshenko_cantilever_deflection(1.0, 0.5 * L, E, nu, b, h)),
                  1.0, 1e-12);
    }
}

// Published roots (Blevins, table 8-1; closed-forms.md) to their five decimals.
TEST(Beams, CantileverFrequencyRoots)
{
  const double published[] = {1.87510, 4.69409, 7.85476, 10.99554};
  for (unsigned int n = 1; n <= 4; ++n)
    {
      const double x = cantilever_frequency_root(n);
      EXPECT_NEAR(x, published[n - 1], 5e-6) << "n = " << n;
      EXPECT_NEAR((1.0 + std::cos(x) * std::cosh(x)) / std::cosh(x), 0.0, 1e-14) << "n = " << n;
    }
  // Asymptote (2n - 1) pi / 2; the difference decays like 2 exp(-x).
  EXPECT_NEAR(cantilever_frequency_root(10), 19.0 * M_PI / 2.0, 1e-12);
  EXPECT_THROW(cantilever_frequency_root(0), std::invalid_argument);
}

// Rayleigh's quotient with the static tip-load shape 3 xi^2 - xi^3 bounds (beta_1 L)^4 from above by
// 12 * 35 / 33 (Rayleigh's principle); it is known to be close (the shapes differ little).
TEST(Beams, FirstFrequencyIsBelowRayleighBound)
{
  const double L = 50.0, rho = 1.2e-9;  // mm, t/mm^3
  const double EI = E * b * h * h * h / 12.0, mass_per_length = rho * b * h;
  const double omega = euler_bernoulli_cantilever_angular_frequency(1, L, E, rho, b, h);
  const double rayleigh = std::sqrt(12.0 * 35.0 / 33.0 * EI / (mass_per_length * std::pow(L, 4)));
  EXPECT_LT(omega, rayleigh);
  EXPECT_GT(omega, rayleigh / 1.02);
  EXPECT_NEAR(euler_bernoulli_cantilever_frequency(1, L, E, rho, b, h), omega / (2.0 * M_PI),
              1e-12 * omega);
}

// Frequencies scale with the square of the roots; the published five-decimal roots fix the ratio to
// 7.5e-6 relative (4.7e-5 absolute).
TEST(Beams, HigherModesScaleWithRootSquared)
{
  const double L = 50.0, rho = 1.2e-9;
  const double f1 = euler_bernoulli_cantilever_frequency(1, L, E, rho, b, h);
  const double f2 = euler_bernoulli_cantilever_frequency(2, L, E, rho, b, h);
  EXPECT_NEAR(f2 / f1, std::pow(4.69409 / 1.87510, 2), 5e-5);
}

TEST(Beams, BadInputThrowsNamingTheParameter)
{
  try
    {
      euler_bernoulli_cantilever_deflection(P, 10.0, E, b, -1.0);
      FAIL() << "no exception";
    }
  catch (const std::invalid_argument &error)
    {
      EXPECT_NE(std::string(error.what()).find("'h'"), std::string::npos) << error.what();
    }
  EXPECT_THROW(timoshenko_cantilever_deflection(P, 10.0, E, 0.6, b, h), std::invalid_argument);
  EXPECT_THROW(euler_bernoulli_guided_stiffness(0.0, E, b, h), std::invalid_argument);
  EXPECT_THROW(euler_bernoulli_cantilever_frequency(1, 10.0, E, -1.0, b, h), std::invalid_argument);
}

// The elasticity solution's shear deflection (4+5nu) P L/(2 E b h) is the Timoshenko beam's
// P L/(kappa G A) with the effective kappa = 4(1+nu)/(4+5nu) (Augarde and Deeks 2008).
TEST(Beams, TimoshenkoGoodierIsABeamWithItsOwnShearCoefficient)
{
  for (const double nu : {0.0, 0.25, 0.3, 0.49})
    {
      const double kappa = 4.0 * (1.0 + nu) / (4.0 + 5.0 * nu);
      const double beam  = closed_forms::timoshenko_cantilever_deflection(2.0, 48.0, 3e4, nu, 1.0, 12.0, kappa);
      EXPECT_NEAR(closed_forms::timoshenko_goodier_cantilever_deflection(2.0, 48.0, 3e4, nu, 1.0, 12.0),
                  beam, 1e-14 * beam);
    }
}

// Euler loads against the column equation EI w'''' + P w'' = 0 solved for each pair of ends: the
// smallest k L = sqrt(P / EI) L is pi/2 (fixed-free), pi (pinned-pinned), the root of tan x = x
// (fixed-pinned, found here by bisection) and 2 pi (fixed-fixed).
TEST(Beams, EulerColumnLoadsMatchTheColumnEquation)
{
  const double L = 40.0, EI = E * second_moment_of_area(b, h);
  double lo = M_PI + 0.1, hi = 1.5 * M_PI - 1e-9; // tan x - x changes sign once on (pi, 3 pi / 2)
  for (int i = 0; i < 200; ++i)
    {
      const double mid = 0.5 * (lo + hi);
      (std::tan(mid) - mid < 0 ? lo : hi) = mid;
    }
  const double fixed_pinned_root = 0.5 * (lo + hi);
  const std::pair<double, double> cases[] = {{2.0, M_PI / 2}, {1.0, M_PI}, {0.5, 2 * M_PI},
                                             {M_PI / fixed_pinned_root, fixed_pinned_root}};
  for (const auto &[K, kL] : cases)
    EXPECT_NEAR(euler_column_load(L, E, b, h, K), kL * kL * EI / (L * L), 1e-12 * EI / (L * L)) << "K = " << K;
  EXPECT_NEAR(M_PI / fixed_pinned_root, 0.6992, 1e-4); // the factor the registry documents
}

// Engesser's load lies below Euler's by 1 / (1 + P_E / (kappa G A)) and tends to it for slender columns.
TEST(Beams, EngesserColumnLoadShearCorrection)
{
  const double L = 40.0, K = 2.0;
  const double euler = euler_column_load(L, E, b, h, K);
  const double kGA   = rectangle_shear_coefficient * E / (2 * (1 + nu)) * b * h;
  EXPECT_NEAR(engesser_column_load(L, E, nu, b, h, K), euler / (1 + euler / kGA), 1e-12 * euler);
  EXPECT_LT(engesser_column_load(L, E, nu, b, h, K), euler);
  const double slender = 100 * L;
  EXPECT_NEAR(engesser_column_load(slender, E, nu, b, h, K) / euler_column_load(slender, E, b, h, K), 1.0, 1e-6);
}

namespace
{
  // End rotation of a cantilever with end moment M and dead axial force P (compressive > 0), from
  // EI w'' = M + P (delta - w), w(0) = w'(0) = 0, delta = w(L): RK4 shooting (linear in delta).
  double shot_end_rotation(const double L, const double EI, const double P, const double M)
  {
    auto shoot = [&](const double delta, double &end_slope) {
      const int n = 4000;
      const double dx = L / n;
      double w = 0, s = 0;
      auto f = [&](double w_) { return (M + P * (delta - w_)) / EI; };
      for (int i = 0; i < n; ++i)
        {
          const double k1w = s, k1s = f(w);
          const double k2w = s + 0.5 * dx * k1s, k2s = f(w + 0.5 * dx * k1w);
          const double k3w = s + 0.5 * dx * k2s, k3s = f(w + 0.5 * dx * k2w);
          const double k4w = s + dx * k3s, k4s = f(w + dx * k3w);
          w += dx / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
          s += dx / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
        }
      end_slope = s;
      return w;
    };
    double s0, s1;
    const double w0 = shoot(0, s0), w1 = shoot(1, s1);
    const double delta = w0 / (1 - (w1 - w0)); // delta = w0 + (w1 - w0) delta
    double slope;
    shoot(delta, slope);
    return slope;
  }
} // namespace

// The beam-column stiffness against the shot solution of its differential equation, in compression
// up to 0.9 of the buckling load and in tension.
TEST(Beams, BeamColumnEndMomentStiffnessMatchesTheShotSolution)
{
  const double L = 40.0, EI = E * second_moment_of_area(b, h), M = 1e-3;
  const double critical = euler_column_load(L, E, b, h, 2.0);
  for (const double fraction : {0.0, 0.5, 0.9, -1.0, -3.0})
    {
      const double P = fraction * critical;
      const double K = beam_column_end_moment_stiffness(L, E, b, h, P);
      EXPECT_NEAR(K * shot_end_rotation(L, EI, P, M) / M, 1.0, 1e-9) << "P = " << fraction << " P_cr";
    }
  EXPECT_NEAR(beam_column_end_moment_stiffness(L, E, b, h, 1e-14), EI / L, 1e-9 * EI / L);
  EXPECT_NEAR(beam_column_end_moment_stiffness(L, E, b, h, critical), 0.0, 1e-12 * EI / L);
}

namespace
{
  // Transverse end force of a fixed-guided beam-column (tension T, end displaced by 1 without turning)
  // by Hermite cubic beam elements with their consistent geometric stiffness: a reference independent
  // of the closed forms, converging like h^4 in the elements' count.
  double guided_stiffness_by_beam_elements(double L, double EI, double T, int n)
  {
    const double l = L / n;
    const int    size = 2 * (n + 1);
    std::vector<std::vector<double>> K(size, std::vector<double>(size, 0.));
    const double ke[4][4] = {{12, 6 * l, -12, 6 * l}, {6 * l, 4 * l * l, -6 * l, 2 * l * l},
                             {-12, -6 * l, 12, -6 * l}, {6 * l, 2 * l * l, -6 * l, 4 * l * l}};
    const double kg[4][4] = {{36, 3 * l, -36, 3 * l}, {3 * l, 4 * l * l, -3 * l, -l * l},
                             {-36, -3 * l, 36, -3 * l}, {3 * l, -l * l, -3 * l, 4 * l * l}};
    for (int e = 0; e < n; ++e)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          K[2 * e + i][2 * e + j] += EI / (l * l * l) * ke[i][j] + T / (30 * l) * kg[i][j];
    // Unknowns: the interior nodes' (w, theta); w(L) = 1, every other end value 0.
    const int m = size - 4;
    std::vector<std::vector<double>> A(m, std::vector<double>(m + 1, 0.));
    for (int i = 0; i < m; ++i)
      {
        for (int j = 0; j < m; ++j)
          A[i][j] = K[i + 2][j + 2];
        A[i][m] = -K[i + 2][size - 2];
      }
    for (int c = 0; c < m; ++c) // Gaussian elimination (the matrix is positive definite below buckling)
      for (int r = c + 1; r < m; ++r)
        {
          const double f = A[r][c] / A[c][c];
          for (int k = c; k <= m; ++k)
            A[r][k] -= f * A[c][k];
        }
    std::vector<double> u(size, 0.);
    u[size - 2] = 1;
    for (int r = m - 1; r >= 0; --r)
      {
        double s = A[r][m];
        for (int k = r + 1; k < m; ++k)
          s -= A[r][k] * u[k + 2];
        u[r + 2] = s / A[r][r];
      }
    double force = 0;
    for (int j = 0; j < size; ++j)
      force += K[size - 2][j] * u[j];
    return force;
  }
} // namespace

TEST(Beams, GuidedBeamColumnAgainstBeamElements)
{
  const double L = 50, E = 2000, b = 3, h = 1;
  const double EI = E * closed_forms::second_moment_of_area(b, h);
  for (const double p : {-9.0, -5.0, -1.0, 0.0, 1e-7, 2.0, 20.0}) // normalized tension P L^2 / E I
    {
      const double T         = p * EI / (L * L);
      const double reference = guided_stiffness_by_beam_elements(L, EI, T, 128);
      const double exact     = closed_forms::guided_beam_column_stiffness(L, E, b, h, -T);
      EXPECT_NEAR(exact / reference, 1.0, 1e-8) << "p = " << p; // 128 elements: 4.8e-9 at p = -9
    }
  EXPECT_NEAR(closed_forms::guided_beam_column_stiffness(L, E, b, h, 0) * L * L * L / EI, 12, 1e-12);
  // Zero at the sway buckling load pi^2 E I / L^2, negative beyond.
  const double critical = M_PI * M_PI * EI / (L * L);
  EXPECT_NEAR(closed_forms::guided_beam_column_stiffness(L, E, b, h, critical) * L * L * L / EI, 0, 1e-9);
  EXPECT_LT(closed_forms::guided_beam_column_stiffness(L, E, b, h, 1.01 * critical), 0);
}

TEST(Beams, BeamConstraintModelIsTheSecondOrderSeries)
{
  const double L = 50, E = 2000, b = 3, h = 1;
  const double EI = E * closed_forms::second_moment_of_area(b, h);
  const auto error = [&](double p) {
    const double P = -p * EI / (L * L); // P > 0 compressive
    return closed_forms::bcm_guided_stiffness(L, E, b, h, P) / closed_forms::guided_beam_column_stiffness(L, E, b, h, P) -
           1;
  };
  // Third order in p: halving p divides the error by about 8, either sign.
  for (const double p : {1.0, -1.0})
    EXPECT_NEAR(error(p) / error(p / 2), 8, 0.8) << "p = " << p;
  EXPECT_LT(std::abs(error(2.5)), 3e-5);
  EXPECT_LT(std::abs(error(-2.5)), 3e-5);
  EXPECT_LT(std::abs(error(-5)), 3.6e-4);
  EXPECT_NEAR(error(-8), 3.9e-3, 1e-4);
  // Registered, with the warning beyond |p| = 5.
  const auto near = closed_forms::evaluate("bcm_guided_stiffness", {{"L", L}, {"E", E}, {"b", b}, {"h", h}, {"P", 0}});
  EXPECT_NEAR(near.value * L * L * L / EI, 12, 1e-12);
  EXPECT_TRUE(near.warnings.empty());
  const auto far = closed_forms::evaluate("bcm_guided_stiffness",
                                          {{"L", L}, {"E", E}, {"b", b}, {"h", h}, {"P", 6 * EI / (L * L)}});
  EXPECT_EQ(far.warnings.size(), 1u);
}
