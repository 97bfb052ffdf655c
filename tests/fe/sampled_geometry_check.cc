// The sampled curves and surfaces of mesh/sampled_geometry.h (plain C++, no gmsh, no deal.II):
// Hermite interpolation reproduces cubics, and the closest point on a sampled ellipse and on a
// sampled torus patch lies on the exact shape to 1e-10 of its size and is the exact foot point (to
// the interpolation's accuracy in the tangent, times the point's distance off the shape).
#include "mesh/sampled_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace compliant;

namespace
{
  // Samples of a parametrization given with its derivatives: x, x_u (curve) or x, x_u, x_v, x_uv.
  using Curve   = std::function<void(double, double *)>;         // writes x, x_u
  using Surface = std::function<void(double, double, double *)>; // writes x, x_u, x_v, x_uv

  ParametricSamples sample_curve(const Curve &curve, const double u0, const double u1, const unsigned int n)
  {
    ParametricSamples s;
    for (unsigned int i = 0; i <= n; ++i)
      {
        s.u.push_back(u0 + (u1 - u0) * i / n);
        double values[6];
        curve(s.u.back(), values);
        s.data.insert(s.data.end(), values, values + 6);
      }
    return s;
  }

  ParametricSamples sample_surface(const Surface &surface, const double u0, const double u1, const double v0,
                                   const double v1, const unsigned int n)
  {
    ParametricSamples s;
    for (unsigned int i = 0; i <= n; ++i)
      s.u.push_back(u0 + (u1 - u0) * i / n), s.v.push_back(v0 + (v1 - v0) * i / n);
    for (const double u : s.u)
      for (const double v : s.v)
        {
          double values[12];
          surface(u, v, values);
          s.data.insert(s.data.end(), values, values + 12);
        }
    return s;
  }

  const double a = 3, b = 1; // the ellipse's half axes
  void ellipse(const double t, double *x)
  {
    const double values[6] = {a * std::cos(t), b * std::sin(t), 0, -a * std::sin(t), b * std::cos(t), 0};
    std::copy(values, values + 6, x);
  }

  // A torus patch (major radius 4, minor 1.5): curved both ways, with a twist-free parametrization.
  void torus(const double u, const double v, double *x)
  {
    const double r = 4 + 1.5 * std::cos(v);
    const double values[12] = {r * std::cos(u), r * std::sin(u), 1.5 * std::sin(v),
                               -r * std::sin(u), r * std::cos(u), 0,
                               -1.5 * std::sin(v) * std::cos(u), -1.5 * std::sin(v) * std::sin(u), 1.5 * std::cos(v),
                               1.5 * std::sin(v) * std::sin(u), -1.5 * std::sin(v) * std::cos(u), 0};
    std::copy(values, values + 12, x);
  }

  double distance(const Vector3 &p, const Vector3 &q)
  {
    return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
  }
} // namespace

TEST(SampledGeometry, HermiteReproducesCubics)
{
  // x(t) = (t^3, 2 t^2 - t, 1) sampled at 4 points: exact everywhere.
  const auto s = sample_curve([](const double t, double *x) {
    const double values[6] = {t * t * t, 2 * t * t - t, 1, 3 * t * t, 4 * t - 1, 0};
    std::copy(values, values + 6, x);
  }, -1, 2, 3);
  for (const double t : {-1., -0.3, 0.77, 1.5, 2.})
    {
      const auto p = evaluate(s, t);
      EXPECT_NEAR(p.x[0], t * t * t, 1e-13);
      EXPECT_NEAR(p.x[1], 2 * t * t - t, 1e-13);
      EXPECT_NEAR(p.x_u[0], 3 * t * t, 1e-12);
      EXPECT_NEAR(p.x_uu[1], 4, 1e-11);
    }
}

TEST(SampledGeometry, ClosestPointOnEllipse)
{
  const SampledShape shape(sample_curve(ellipse, 0, M_PI, 400));
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> angle(0.05, M_PI - 0.05), offset(-0.05, 0.05);
  for (unsigned int k = 0; k < 200; ++k)
    {
      // A point off the ellipse along its normal at t: its foot is the point at t.
      const double t = angle(random), h = offset(random);
      double       x[6];
      ellipse(t, x);
      const double n[2] = {x[4], -x[3]}, length = std::hypot(n[0], n[1]);
      const Vector3 p = {{x[0] + h * n[0] / length, x[1] + h * n[1] / length, 0}};
      std::array<double, 2> parameters;
      const Vector3         foot = shape.closest_point(p, &parameters);
      EXPECT_NEAR(foot[0] * foot[0] / (a * a) + foot[1] * foot[1] / (b * b), 1, 1e-10) << "t = " << t;
      EXPECT_LT(distance(foot, {{x[0], x[1], 0}}), 1e-9 * a) << "t = " << t;
      EXPECT_NEAR(parameters[0], t, 1e-9);
    }
  // The average of two points of the ellipse goes back onto it, between them.
  double x0[6], x1[6];
  ellipse(0.4, x0), ellipse(0.5, x1);
  const Vector3 mid = shape.project_average({{{x0[0], x0[1], 0}}, {{x1[0], x1[1], 0}}}, {0.5, 0.5});
  EXPECT_NEAR(mid[0] * mid[0] / (a * a) + mid[1] * mid[1] / (b * b), 1, 1e-10);
  EXPECT_TRUE(mid[0] < x0[0] && mid[0] > x1[0]);
}

TEST(SampledGeometry, ClosestPointOnTorus)
{
  const SampledShape shape(sample_surface(torus, 0, M_PI / 2, -M_PI / 2, M_PI / 2, 256));
  std::mt19937                           random(11);
  std::uniform_real_distribution<double> u_of(0.1, M_PI / 2 - 0.1), v_of(-1.4, 1.4), offset(-0.1, 0.1);
  for (unsigned int k = 0; k < 200; ++k)
    {
      const double u = u_of(random), v = v_of(random), h = offset(random);
      double       x[12];
      torus(u, v, x);
      // The torus's unit normal at (u, v) points from the tube's centre line.
      const Vector3 normal = {{std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)}};
      const Vector3 p      = {{x[0] + h * normal[0], x[1] + h * normal[1], x[2] + h * normal[2]}};
      std::array<double, 2> parameters;
      const Vector3         foot = shape.closest_point(p, &parameters);
      const double from_axis = std::hypot(foot[0], foot[1]) - 4;
      EXPECT_NEAR(std::hypot(from_axis, foot[2]), 1.5, 1e-10 * 5.5) << "u = " << u << ", v = " << v;
      EXPECT_LT(distance(foot, {{x[0], x[1], x[2]}}), 1e-9 * 5.5) << "u = " << u << ", v = " << v;
      EXPECT_NEAR(parameters[0], u, 1e-9);
      EXPECT_NEAR(parameters[1], v, 1e-9);
    }
}
