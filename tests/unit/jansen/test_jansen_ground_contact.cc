// The ground-contact pose: the crank angle where the foot H is lowest.
#include <mechanisms/jansen/jansen_crank_turn.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace compliant::jansen;

// Reference: brute-force scan of y_H every 0.01 deg. Near a minimum
// y = y_min + c (d theta)^2 / 2 with c <= 1000 mm/rad^2 on this leg, so the
// scan's best sample lies within 500 (0.005 deg = 8.7e-5 rad)^2 = 4e-6 mm of
// the true minimum, and the refined minimum must be no higher than any sample
// (up to round-off).
TEST(JansenGroundContact, LowestFootAgreesWithABruteForceScan)
{
  const JansenLinkLengths l       = paper_link_lengths();
  const GroundContact     contact = find_ground_contact(l);
  double                  scan_min = INFINITY, scan_theta = 0.;
  for (int i = 0; i < 36000; ++i)
    {
      const double theta2 = i * 0.01 * M_PI / 180.;
      const double y      = joint_positions(l, theta2)[Joint::H].y;
      if (y < scan_min)
        {
          scan_min   = y;
          scan_theta = theta2;
        }
    }
  EXPECT_LE(contact.lowest.foot.y, scan_min + 1e-9);
  EXPECT_GT(contact.lowest.foot.y, scan_min - 1e-5);
  EXPECT_NEAR(contact.lowest.theta2, scan_theta, 0.01 * M_PI / 180.);
  EXPECT_EQ(contact.lowest.foot.y, contact.local_minima.front().foot.y);
}

// At each reported minimum the foot height is stationary in the crank angle
// (central difference of the position analysis, h = 1e-5 rad: truncation
// ~h^2 y''' ~ 1e-8 mm/rad) and rises on both sides.
TEST(JansenGroundContact, MinimaAreStationaryAndRiseOnBothSides)
{
  const JansenLinkLengths l       = paper_link_lengths();
  const GroundContact     contact = find_ground_contact(l);
  ASSERT_GE(contact.local_minima.size(), 1u);
  for (const FootLowPoint &m : contact.local_minima)
    {
      const auto   y = [&](const double t) { return joint_positions(l, t)[Joint::H].y; };
      const double h = 1e-5;
      EXPECT_NEAR((y(m.theta2 + h) - y(m.theta2 - h)) / (2. * h), 0., 1e-6);
      EXPECT_GT(y(m.theta2 + 1e-2), m.foot.y);
      EXPECT_GT(y(m.theta2 - 1e-2), m.foot.y);
    }
}

TEST(JansenGroundContact, RejectsTooFewSamples)
{
  EXPECT_THROW(find_ground_contact(paper_link_lengths(), 4), std::invalid_argument);
  EXPECT_THROW(sweep_crank_turn(paper_link_lengths(), 10., 0), std::invalid_argument);
}
