// The shapes mesh/curved_entities.h recognises in a gmsh geometry, against the geometry that was
// drawn: a circle's centre and radius, a cylinder on an oblique axis, a sphere; an ellipse, a
// spline and a torus are curved but none of these (followed through samples of their
// parametrization, on the shape to 1e-9); planes and lines are not reported at all.
#include "mesh/gmsh_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace compliant;

namespace
{
  MeshedGeometry mesh_text(const std::string &name, const std::string &text)
  {
    const std::string file = "/tmp/compliant-curved-" + name + ".geo";
    std::ofstream(file) << text;
    MeshedGeometry geometry = mesh_geometry(file, {});
    std::remove(file.c_str());
    return geometry;
  }

  int count_named(const CurvedEntities &curved, const std::string &word)
  {
    int n = 0;
    for (const auto &s : curved.straightened)
      n += s.find(word) != std::string::npos;
    return n;
  }
} // namespace

TEST(CurvedEntities, PlaneShapes)
{
  // A plate with a circular hole (centre (5, 4), r = 1.5), an elliptic hole and a spline edge.
  const auto g = mesh_text("plane", R"(
    Point(1) = {0, 0, 0, 1}; Point(2) = {12, 0, 0, 1}; Point(3) = {12, 8, 0, 1}; Point(4) = {6, 9, 0, 1};
    Point(5) = {0, 8, 0, 1};
    Line(1) = {1, 2}; Line(2) = {2, 3}; BSpline(3) = {3, 4, 5}; Line(4) = {5, 1};
    Point(10) = {5, 4, 0, 0.3}; Point(11) = {6.5, 4, 0, 0.3}; Point(12) = {5, 5.5, 0, 0.3};
    Point(13) = {3.5, 4, 0, 0.3}; Point(14) = {5, 2.5, 0, 0.3};
    Circle(11) = {11, 10, 12}; Circle(12) = {12, 10, 13}; Circle(13) = {13, 10, 14}; Circle(14) = {14, 10, 11};
    Point(20) = {9.5, 4, 0, 0.3}; Point(21) = {10.5, 4, 0, 0.3}; Point(22) = {9.5, 6, 0, 0.3};
    Point(23) = {8.5, 4, 0, 0.3}; Point(24) = {9.5, 2, 0, 0.3};
    Ellipse(21) = {21, 20, 22, 22}; Ellipse(22) = {22, 20, 23, 23}; Ellipse(23) = {23, 20, 24, 24};
    Ellipse(24) = {24, 20, 21, 21};
    Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {11, 12, 13, 14}; Curve Loop(3) = {21, 22, 23, 24};
    Plane Surface(1) = {1, 2, 3};
    Physical Curve("outside") = {1, 2, 3, 4}; Physical Surface("body") = {1};
  )");
  ASSERT_EQ(g.curved.exact.size(), 9u); // the hole's four arcs, the ellipse's four, the spline
  int ellipse_arcs = 0;
  for (const auto &arc : g.curved.exact)
    if (arc.shape == CurvedBoundary::sampled_curve)
      {
        for (std::size_t i = 0; i < arc.samples.u.size(); ++i)
          {
            const double *x = arc.samples.data.data() + 6 * i;
            if (std::abs(x[0] - 9.5) < 1.01 && std::abs(x[1] - 4) < 2.01) // an ellipse arc's sample
              {
                EXPECT_NEAR((x[0] - 9.5) * (x[0] - 9.5) + (x[1] - 4) * (x[1] - 4) / 4, 1, 1e-11);
              }
          }
        ellipse_arcs += arc.samples.data[1] < 7; // the spline runs at y >= 8
      }
  EXPECT_EQ(ellipse_arcs, 4);
  for (const auto &arc : g.curved.exact)
    if (arc.shape != CurvedBoundary::sampled_curve)
      {
        EXPECT_EQ(arc.shape, CurvedBoundary::circle);
        EXPECT_NEAR(arc.centre[0], 5, 1e-9);
        EXPECT_NEAR(arc.centre[1], 4, 1e-9);
        EXPECT_NEAR(arc.radius, 1.5, 1e-9);
        EXPECT_FALSE(arc.face_centres.empty());
      }
  EXPECT_TRUE(g.curved.straightened.empty()); // every curve followed, nothing straight reported
}

TEST(CurvedEntities, SolidShapes)
{
  // A box with a bore on the oblique axis (1, 1, 1), a spherical cavity and a toroidal one.
  const auto g = mesh_text("solid", R"(
    SetFactory("OpenCASCADE");
    Mesh.MeshSizeMax = 1.5;
    Box(1) = {0, 0, 0, 10, 10, 10};
    Cylinder(2) = {-1, -1, -1, 12, 12, 12, 1.2};
    Sphere(3) = {2, 7, 5, 1.4};
    Torus(4) = {7.5, 2.5, 5, 1.3, 0.5};
    BooleanDifference(5) = {Volume{1}; Delete;}{Volume{2, 3, 4}; Delete;};
    Physical Volume("body") = {5};
  )");
  int cylinders = 0, spheres = 0, others = 0;
  for (const auto &s : g.curved.exact)
    if (s.shape == CurvedBoundary::cylinder)
      {
        ++cylinders;
        const double along = (s.axis[0] + s.axis[1] + s.axis[2]) / std::sqrt(3.);
        EXPECT_NEAR(std::abs(along), 1, 1e-9);
        EXPECT_NEAR(s.radius, 1.2, 1e-9);
        // The centre recorded is a point of the axis: equal coordinates.
        EXPECT_NEAR(s.centre[0], s.centre[1], 1e-8);
        EXPECT_NEAR(s.centre[1], s.centre[2], 1e-8);
      }
    else if (s.shape == CurvedBoundary::sphere)
      {
        ++spheres;
        EXPECT_NEAR(s.centre[0], 2, 1e-9);
        EXPECT_NEAR(s.centre[1], 7, 1e-9);
        EXPECT_NEAR(s.centre[2], 5, 1e-9);
        EXPECT_NEAR(s.radius, 1.4, 1e-9);
      }
    else if (s.shape == CurvedBoundary::sampled_surface)
      {
        // The torus: its samples on (rho - 1.3)^2 + (z - 5)^2 = 0.5^2, rho from its axis.
        ++others;
        for (std::size_t k = 0; k < s.samples.data.size(); k += 12)
          {
            const double *x   = s.samples.data.data() + k;
            const double  rho = std::hypot(x[0] - 7.5, x[1] - 2.5) - 1.3;
            EXPECT_NEAR(std::hypot(rho, x[2] - 5), 0.5, 1e-9);
          }
      }
  EXPECT_GE(cylinders, 1);
  EXPECT_GE(spheres, 1);
  EXPECT_EQ(others, 1);
  EXPECT_TRUE(g.curved.straightened.empty());
  EXPECT_EQ(count_named(g.curved, "Plane"), 0);
}
