// Reentrant-corner detection on deal.II's own L-shaped and square meshes, whose corners are known
// by construction.
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include "section/boundary_corners.h"

#include <gtest/gtest.h>

#include <cmath>

using compliant::section::reentrant_corners;

namespace
{
  constexpr double five_degrees = 5 * M_PI / 180;
}

TEST(BoundaryCorners, LShapeHasOneReentrantCornerOf270Degrees)
{
  for (unsigned int refinements = 0; refinements < 3; ++refinements)
    {
      dealii::Triangulation<2> triangulation;
      // [-1, 1]^2 without the quadrant (0, 1) x (0, 1): the concave corner is the origin.
      dealii::GridGenerator::hyper_L(triangulation, -1, 1);
      triangulation.refine_global(refinements);
      const auto corners = reentrant_corners(triangulation, five_degrees);
      ASSERT_EQ(corners.size(), 1u) << "refinements " << refinements;
      EXPECT_NEAR(corners[0].location.norm(), 0.0, 1e-14);
      EXPECT_NEAR(corners[0].interior_angle, 1.5 * M_PI, 1e-12);
      // Cells of the L are squares of side 1 / 2^refinements.
      EXPECT_NEAR(corners[0].cell_size, std::sqrt(2.0) / (1 << refinements), 1e-12);
    }
}

TEST(BoundaryCorners, ConvexShapesHaveNone)
{
  dealii::Triangulation<2> square;
  dealii::GridGenerator::subdivided_hyper_rectangle(square, {3, 2}, dealii::Point<2>(0, 0),
                                                    dealii::Point<2>(3, 1));
  EXPECT_TRUE(reentrant_corners(square, five_degrees).empty());

  // A disk's boundary polygon turns by 360/n degrees at each vertex, all convex.
  dealii::Triangulation<2> disk;
  dealii::GridGenerator::hyper_ball(disk);
  disk.refine_global(2);
  EXPECT_TRUE(reentrant_corners(disk, 0.0).empty());
}

TEST(BoundaryCorners, HoleCornersAreReentrant)
{
  // A square plate with a square hole: the four corners of the hole are concave (270 degrees)
  // seen from the material.
  dealii::Triangulation<2> plate;
  dealii::GridGenerator::hyper_cube_with_cylindrical_hole(plate, 0.25, 1.0);
  // Without a manifold the hole is the polygon through the 8 gmsh-like vertices at radius 0.25:
  // a regular octagon, whose interior angles seen from the plate are 360 - 135 = 225 degrees.
  plate.reset_all_manifolds();
  const auto corners = reentrant_corners(plate, five_degrees);
  ASSERT_EQ(corners.size(), 8u);
  for (const auto &c : corners)
    {
      EXPECT_NEAR(c.location.norm(), 0.25, 1e-12);
      EXPECT_NEAR(c.interior_angle, 225 * M_PI / 180, 1e-12);
    }
}
