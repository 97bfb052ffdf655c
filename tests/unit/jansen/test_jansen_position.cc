// Position analysis of the Jansen leg: assembly from the link lengths alone.
#include <mechanisms/jansen/jansen_position_analysis.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <tuple>
#include <vector>

using namespace compliant::jansen;

namespace
{
  constexpr double degree = M_PI / 180.;

  double angle_gap_degrees(const double a, const double b)
  {
    return std::abs(std::remainder(a - b, 2. * M_PI)) / degree;
  }
} // namespace

// The paper's printed angles at theta2 = 302.8 deg (Kartal & Kavlak, sec.
// III.A), given to 0.01 deg and read off a Cinderella drawing: assembling from
// the lengths alone with the default branches must reproduce them to that
// precision. This also fixes the crank-angle convention: the paper's theta2 is
// our theta2 (direction of A->B from the horizontal).
TEST(JansenPosition, ReproducesThePapersPrintedAnglesAtItsCrankAngle)
{
  const JansenPose pose = solve_position(paper_link_lengths(), 302.8 * degree);
  const LinkAngles &a   = pose.angles;
  const double      tolerance = 0.006; // deg: half the printed 0.01 plus drawing precision
  EXPECT_LT(angle_gap_degrees(a.theta3, 123.21 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta4, 213.43 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta5, 243.15 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta5p, 149.42 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta6, 81.9 * degree), 0.05 + tolerance); // printed to 0.1
  EXPECT_LT(angle_gap_degrees(a.theta7, 267.53 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta8, 326.98 * degree), tolerance);
  EXPECT_LT(angle_gap_degrees(a.theta8p, 246.01 * degree), tolerance);
}

// theta1 = 11.6 deg is the direction of E->A in a frame whose x axis is the
// ground: Jansen's crank axle sits a = 38 to the side and l = 7.8 above the
// pivot (scaled by 5), so |EA| = 5 sqrt(38^2 + 7.8^2) and atan(7.8/38) = 11.60.
TEST(JansenPosition, GroundLinkIsJansensAxleOffset)
{
  const JointVectors p = joint_positions(paper_link_lengths(), 0.);
  const PlanarVector ea = p[Joint::A] - p[Joint::E];
  EXPECT_NEAR(ea.x, 5. * 38., 0.01);  // paper's |EA| and theta1 are rounded to 0.01 mm, 0.1 deg
  EXPECT_NEAR(ea.y, 5. * 7.8, 0.2);
  EXPECT_NEAR(norm(ea), 5. * std::hypot(38., 7.8), 0.005);
}

// Twelve pin-to-pin distances equal the link lengths, and the loop equations
// close to round-off, at every crank angle of a full turn.
TEST(JansenPosition, LinkLengthsAndLoopsHoldOverAFullTurn)
{
  const JansenLinkLengths l = paper_link_lengths();
  using J                   = Joint;
  const std::vector<std::tuple<Joint, Joint, double>> links = {
    {J::E, J::A, l.ea}, {J::A, J::B, l.ab}, {J::B, J::C, l.bc}, {J::B, J::G, l.bg},
    {J::C, J::E, l.ce}, {J::D, J::E, l.de}, {J::C, J::D, l.cd}, {J::E, J::G, l.eg},
    {J::D, J::F, l.df}, {J::F, J::G, l.fg}, {J::G, J::H, l.gh}, {J::F, J::H, l.fh}};
  // Round-off: a few ulp of coordinates of ~400 mm (ulp ~ 6e-14) times the
  // chain of five dyads.
  const double round_off = 1e-11;
  double       largest_length_error = 0., largest_residual = 0.;
  for (int i = 0; i < 720; ++i)
    {
      const JansenPose pose = solve_position(l, i * 0.5 * degree);
      for (const auto &[from, to, length] : links)
        largest_length_error = std::max(
          largest_length_error, std::abs(norm(pose.positions[to] - pose.positions[from]) - length));
      for (const double r : loop_closure_residuals(l, pose))
        largest_residual = std::max(largest_residual, std::abs(r));
    }
  EXPECT_LT(largest_length_error, round_off);
  EXPECT_LT(largest_residual, round_off);
}

// The ternary links stay rigid: the angle between their two sides equals the
// law-of-cosines angle of the triangle at every crank angle.
TEST(JansenPosition, TernaryLinksKeepTheirTriangleAngle)
{
  const JansenLinkLengths l = paper_link_lengths();
  // Angle at E between E->C and E->D; at G between G->F and G->H.
  const double at_e = std::acos((l.ce * l.ce + l.de * l.de - l.cd * l.cd) / (2. * l.ce * l.de));
  const double at_g = std::acos((l.fg * l.fg + l.gh * l.gh - l.fh * l.fh) / (2. * l.fg * l.gh));
  for (int i = 0; i < 360; i += 7)
    {
      const LinkAngles a = solve_position(l, i * degree).angles;
      // E->C is theta5 + pi; G->F is theta8 + pi.
      EXPECT_NEAR(std::abs(std::remainder(a.theta5p - (a.theta5 + M_PI), 2. * M_PI)), at_e, 1e-12);
      EXPECT_NEAR(std::abs(std::remainder(a.theta8p - (a.theta8 + M_PI), 2. * M_PI)), at_g, 1e-12);
    }
}

TEST(JansenPosition, RejectsBadInput)
{
  JansenLinkLengths l = paper_link_lengths();
  l.bg                = -1.;
  EXPECT_THROW(solve_position(l, 0.), std::invalid_argument);

  l    = paper_link_lengths();
  l.cd = l.ce + l.de + 1.; // CDE cannot be a triangle
  EXPECT_THROW(solve_position(l, 0.), std::invalid_argument);

  // BC too short to reach from B to the circle around E at some crank angles.
  l    = paper_link_lengths();
  l.bc = 60.;
  bool thrown = false;
  for (int i = 0; i < 360 && !thrown; i += 10)
    try
      {
        solve_position(l, i * degree);
      }
    catch (const std::invalid_argument &e)
      {
        thrown = true;
        EXPECT_NE(std::string(e.what()).find("joint C"), std::string::npos) << e.what();
      }
  EXPECT_TRUE(thrown);

  EXPECT_THROW(solve_position(paper_link_lengths(), std::nan("")), std::invalid_argument);
}
