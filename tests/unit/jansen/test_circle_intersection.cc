#include <mechanisms/jansen/circle_intersection.h>

#include <gtest/gtest.h>

using namespace compliant::jansen;

// 3-4-5 right triangle: centres (0,0) and (5,0), radii 3 and 4. The apex lies
// at (9/5, +-12/5) (altitude of the triangle on the hypotenuse).
TEST(CircleIntersection, RightTriangleApex)
{
  const auto left  = intersect_circles({0., 0.}, 3., {5., 0.}, 4., Side::left);
  const auto right = intersect_circles({0., 0.}, 3., {5., 0.}, 4., Side::right);
  ASSERT_TRUE(left && right);
  EXPECT_NEAR(left->x, 1.8, 1e-14);
  EXPECT_NEAR(left->y, 2.4, 1e-14);
  EXPECT_NEAR(right->x, 1.8, 1e-14);
  EXPECT_NEAR(right->y, -2.4, 1e-14);
}

// Arbitrary placement: the point must lie on both circles, on the asked side.
TEST(CircleIntersection, LiesOnBothCirclesOnTheRequestedSide)
{
  const PlanarVector p{12.5, -3.}, q{-40., 71.};
  for (const Side side : {Side::left, Side::right})
    {
      const auto x = intersect_circles(p, 70., q, 60., side);
      ASSERT_TRUE(x);
      EXPECT_NEAR(norm(*x - p), 70., 1e-12);
      EXPECT_NEAR(norm(*x - q), 60., 1e-12);
      EXPECT_GT(static_cast<int>(side) * cross(q - p, *x - p), 0.);
    }
}

TEST(CircleIntersection, NoIntersectionWhenOutOfReach)
{
  EXPECT_FALSE(intersect_circles({0., 0.}, 1., {5., 0.}, 2., Side::left));      // too far
  EXPECT_FALSE(intersect_circles({0., 0.}, 10., {1., 0.}, 2., Side::left));     // inside
  EXPECT_FALSE(intersect_circles({1., 1.}, 1., {1., 1.}, 1., Side::left));      // concentric
}
