// Arc-length continuation on systems with closed-form equilibrium paths: a softening spring
// through both limit points of its load (load control stops at the first), a spring in series
// with it whose load point snaps back (displacement control of that point cannot pass either),
// and a two-unknown column whose straight path crosses a bifurcation. Every accepted state must be
// an equilibrium, the limit loads must be found with their kind, the path must end at the end
// load factor exactly.
#include "nonlinear/arc_length.h"

#include <gtest/gtest.h>

#include "softening_spring.h"

#include <array>
#include <vector>

using namespace compliant;
namespace ss = softening_spring;

namespace
{
  using Vector2 = std::array<double, 2>;

  // A two-unknown system with energy Pi(v, w) - lambda P . (v, w): gradient and Hessian supplied.
  struct TwoUnknowns : ContinuationSystem<Vector2>
  {
    std::function<Vector2(const Vector2 &)>                  internal_force;
    std::function<std::array<double, 4>(const Vector2 &)>    stiffness; // row-major, symmetric
    Vector2                                                  load;
    std::array<double, 4>                                    K{};
    Vector2                                                  r{};
    bool                                                     stop = false;
    unsigned int                                             linearizations = 0;

    Vector2 last_linearized{};
    // Like the finite-strain problem (rigid boundaries), a correction must start from the state of
    // the latest linearization.
    mutable unsigned int corrections_from_elsewhere = 0;

    Linearization linearize(const Vector2 &u, double lambda) override
    {
      ++linearizations;
      last_linearized = u;
      const Vector2 f = internal_force(u);
      r               = {lambda * load[0] - f[0], lambda * load[1] - f[1]};
      K               = stiffness(u);
      return {std::hypot(r[0], r[1]), std::max(std::hypot(f[0], f[1]), 1e-3)};
    }
    int solve(Vector2 &du_residual, Vector2 &du_load) override
    {
      const double det = K[0] * K[3] - K[1] * K[2];
      if (std::abs(det) < 1e-300)
        throw StepFailure("singular");
      const auto inverse = [&](const Vector2 &b) {
        return Vector2{(K[3] * b[0] - K[1] * b[1]) / det, (-K[2] * b[0] + K[0] * b[1]) / det};
      };
      du_residual = inverse(r);
      du_load     = inverse(load);
      // inertia of a symmetric 2x2 matrix
      return det < 0 ? 1 : (K[0] + K[3] < 0 ? 2 : 0);
    }
    void add_correction(Vector2 &u, double alpha, const Vector2 &du) const override
    {
      if (u != last_linearized)
        ++corrections_from_elsewhere;
      add(u, alpha, du);
    }
    void add(Vector2 &y, double a, const Vector2 &x) const override
    {
      y[0] += a * x[0];
      y[1] += a * x[1];
    }
    double dot(const Vector2 &a, const Vector2 &b) const override { return a[0] * b[0] + a[1] * b[1]; }
    bool   stop_requested() override { return stop; }
  };

  // The softening spring on the second unknown, tied to the first (the load point) by a spring of
  // stiffness k: v = w + f(w) / k along the path, which snaps back in v where f'(w) < -k.
  TwoUnknowns spring_in_series(const double k, const double P)
  {
    TwoUnknowns s;
    s.internal_force = [k](const Vector2 &u) {
      return Vector2{k * (u[0] - u[1]), -k * (u[0] - u[1]) + ss::force(u[1])};
    };
    s.stiffness = [k](const Vector2 &u) { return std::array<double, 4>{k, -k, -k, k + ss::stiffness(u[1])}; };
    s.load      = {P, 0};
    return s;
  }

  struct Recorded
  {
    std::vector<Vector2> states;
    std::vector<double>  load_factors;
    std::vector<int>     unstable;
  };

  ArcLengthResult follow(TwoUnknowns &system, Vector2 &u, double &lambda, const ArcLengthSettings &settings,
                         Recorded &recorded)
  {
    return follow_arc_length<Vector2>(system, u, lambda, settings,
                                      [&](const ArcLengthStep &step, const Vector2 &state) {
                                        recorded.states.push_back(state);
                                        recorded.load_factors.push_back(step.load_factor);
                                        recorded.unstable.push_back(step.unstable_modes);
                                      });
  }
} // namespace

// The stiff series spring (k = 100) makes the load point follow the softening spring: the load
// rises to f(u1), falls to f(u2) and rises again to lambda = 1 (P = 0.5 is past f(u1) = 0.201).
TEST(ArcLength, SofteningSpringThroughBothLimitPoints)
{
  const double      P = 0.5, k = 100;
  TwoUnknowns       system = spring_in_series(k, P);
  Vector2           u{0, 0};
  double            lambda = 0;
  ArcLengthSettings settings;
  Recorded          recorded;
  const auto        result = follow(system, u, lambda, settings, recorded);
  ASSERT_TRUE(result.failure.empty()) << result.failure;
  EXPECT_EQ(lambda, 1.0);
  EXPECT_EQ(system.corrections_from_elsewhere, 0u);
  for (std::size_t i = 0; i < recorded.states.size(); ++i)
    {
      const auto &s = recorded.states[i];
      EXPECT_NEAR(ss::force(s[1]), recorded.load_factors[i] * P, 1e-8);
      EXPECT_NEAR(k * (s[0] - s[1]), recorded.load_factors[i] * P, 1e-8);
    }
  // the end state on the third branch: f(w) = P with f'(w) > 0 beyond the second limit point
  const double u2 = (3 + std::sqrt(1.8)) / 3.6;
  EXPECT_GT(u[1], u2);
  EXPECT_NEAR(ss::force(u[1]), P, 1e-9);
  ASSERT_EQ(result.critical_points.size(), 2u);
  const auto &first = result.critical_points[0], &second = result.critical_points[1];
  EXPECT_EQ(first.kind, CriticalPoint::Kind::limit_point);
  EXPECT_EQ(second.kind, CriticalPoint::Kind::limit_point);
  EXPECT_EQ(first.unstable_before, 0);
  EXPECT_EQ(first.unstable_after, 1);
  EXPECT_EQ(second.unstable_after, 0);
  // The cubic through the steps either side, after the second approach in steps 8 times shorter
  // (1e-6 measured: the cubic's error falls with the fourth power of the step)
  EXPECT_NEAR(first.load_factor, ss::limit_force() / P, 1e-5);
  EXPECT_NEAR(second.load_factor, ss::force(u2) / P, 1e-5);
  EXPECT_GE(first.load_factor, first.bracket_high - 1e-12);
}

// A soft series spring (k = 0.1 < max(-f') = 0.25): the load point's displacement v turns back
// (a snap-back). Arc-length passes it; every state is an equilibrium and v is not monotone.
TEST(ArcLength, SnapBackOfTheLoadPoint)
{
  const double      P = 0.5, k = 0.1;
  TwoUnknowns       system = spring_in_series(k, P);
  Vector2           u{0, 0};
  double            lambda = 0;
  ArcLengthSettings settings;
  Recorded          recorded;
  const auto        result = follow(system, u, lambda, settings, recorded);
  ASSERT_TRUE(result.failure.empty()) << result.failure;
  EXPECT_EQ(lambda, 1.0);
  bool   v_turned_back = false;
  double v_max         = -1e300;
  for (std::size_t i = 0; i < recorded.states.size(); ++i)
    {
      const auto &s = recorded.states[i];
      EXPECT_NEAR(s[0], s[1] + ss::force(s[1]) / k, 1e-7);
      EXPECT_NEAR(ss::force(s[1]), recorded.load_factors[i] * P, 1e-8);
      v_turned_back = v_turned_back || s[0] < v_max - 1e-3;
      v_max         = std::max(v_max, s[0]);
    }
  EXPECT_TRUE(v_turned_back);
  // the same two limit points of the load; coarser steps here (the arc is mostly v): 7e-4 measured
  ASSERT_EQ(result.critical_points.size(), 2u);
  EXPECT_NEAR(result.critical_points[0].load_factor, ss::limit_force() / P, 2e-3);
  EXPECT_NEAR(result.critical_points[1].load_factor, ss::force((3 + std::sqrt(1.8)) / 3.6) / P, 2e-3);
}

// Pi = k1/2 v^2 + w^2/2 (c - v) + w^4/4 - lambda P v: the straight path w = 0 loses stability at
// v = c (lambda = c k1 / P) to a transverse mode orthogonal to the load. The load factor goes on
// rising through it: a bifurcation, not a limit point.
TEST(ArcLength, BifurcationOnTheStraightPath)
{
  const double k1 = 2, c = 0.5, P = 1.6; // lambda_c = 0.625
  TwoUnknowns  system;
  system.internal_force = [=](const Vector2 &u) {
    return Vector2{k1 * u[0] - 0.5 * u[1] * u[1], u[1] * (c - u[0]) + u[1] * u[1] * u[1]};
  };
  system.stiffness = [=](const Vector2 &u) {
    return std::array<double, 4>{k1, -u[1], -u[1], c - u[0] + 3 * u[1] * u[1]};
  };
  system.load = {P, 0};
  Vector2           u{0, 0};
  double            lambda = 0;
  ArcLengthSettings settings;
  Recorded          recorded;
  const auto        result = follow(system, u, lambda, settings, recorded);
  ASSERT_TRUE(result.failure.empty()) << result.failure;
  ASSERT_EQ(result.critical_points.size(), 1u);
  const auto &point = result.critical_points[0];
  EXPECT_EQ(point.kind, CriticalPoint::Kind::bifurcation);
  EXPECT_LE(point.bracket_low, c * k1 / P);
  EXPECT_GE(point.bracket_high, c * k1 / P);
  EXPECT_NEAR(u[0], P / k1, 1e-12);
}

// The step grows on an easy path (a linear spring takes one iteration per step), stays below the
// maximum, and the run stops when asked.
TEST(ArcLength, StepGrowthAndInterruption)
{
  TwoUnknowns system;
  system.internal_force = [](const Vector2 &u) { return Vector2{2 * u[0], 3 * u[1]}; };
  system.stiffness      = [](const Vector2 &) { return std::array<double, 4>{2, 0, 0, 3}; };
  system.load           = {1, 1};
  Vector2           u{0, 0};
  double            lambda = 0;
  ArcLengthSettings settings;
  settings.initial_step = 0.01;
  settings.maximum_step = 0.1;
  Recorded   recorded;
  const auto result = follow(system, u, lambda, settings, recorded);
  ASSERT_TRUE(result.failure.empty());
  ASSERT_GE(recorded.load_factors.size(), 3u);
  EXPECT_NEAR(recorded.load_factors[0], 0.01, 1e-12);
  EXPECT_NEAR(recorded.load_factors[1] - recorded.load_factors[0], 0.015, 1e-12);
  for (std::size_t i = 1; i < recorded.load_factors.size(); ++i)
    EXPECT_LE(recorded.load_factors[i] - recorded.load_factors[i - 1], 0.1 + 1e-12);
  EXPECT_NEAR(u[0], 0.5, 1e-12);

  u = {0, 0}, lambda = 0;
  system.stop = true;
  Recorded none;
  EXPECT_TRUE(follow(system, u, lambda, settings, none).interrupted);
  EXPECT_TRUE(none.states.empty());
}

// Any end load factor is met exactly, once (the path's last step is solved there).
TEST(ArcLength, EndsExactlyAtAnyEndLoadFactor)
{
  for (const double end : {0.3, 0.7, 0.123456789})
    {
      TwoUnknowns       system = spring_in_series(100, 0.5);
      Vector2           u{0, 0};
      double            lambda = 0;
      ArcLengthSettings settings;
      settings.end_load_factor = end;
      Recorded   recorded;
      const auto result = follow(system, u, lambda, settings, recorded);
      ASSERT_TRUE(result.failure.empty()) << result.failure;
      EXPECT_EQ(lambda, end);
      EXPECT_EQ(recorded.load_factors.back(), end);
      EXPECT_LT(recorded.load_factors[recorded.load_factors.size() - 2], end);
      EXPECT_NEAR(ss::force(u[1]), end * 0.5, 1e-9);
      EXPECT_EQ(system.corrections_from_elsewhere, 0u);
    }
}

// No load: a clear failure, not a division by zero.
TEST(ArcLength, ZeroLoadPattern)
{
  TwoUnknowns system = spring_in_series(1, 0);
  Vector2     u{0, 0};
  double      lambda = 0;
  Recorded    recorded;
  const auto  result = follow(system, u, lambda, ArcLengthSettings{}, recorded);
  EXPECT_NE(result.failure.find("load pattern is zero"), std::string::npos);
}
