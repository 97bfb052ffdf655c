#include <mechanisms/jansen/jansen_position_analysis.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      PlanarVector close_dyad(const PlanarVector &first_centre,
                              const double        first_radius,
                              const PlanarVector &second_centre,
                              const double        second_radius,
                              const Side          side,
                              const char         *joint,
                              const double        theta2)
      {
        const auto point =
          intersect_circles(first_centre, first_radius, second_centre, second_radius, side);
        if (!point)
          throw std::invalid_argument(
            std::string("solve_position: the Jansen leg cannot be assembled at crank angle "
                        "theta2 = ") +
            std::to_string(theta2 * 180. / M_PI) + " deg: joint " + joint +
            " is out of reach (centre distance " +
            std::to_string(norm(second_centre - first_centre)) + ", link lengths " +
            std::to_string(first_radius) + " and " + std::to_string(second_radius) + ")");
        return *point;
      }
    } // namespace

    JansenPose solve_position(const JansenLinkLengths &lengths,
                              const double             theta2,
                              const AssemblyBranches  &branches)
    {
      validate(lengths);
      if (!std::isfinite(theta2))
        throw std::invalid_argument("solve_position: crank angle theta2 must be finite");

      JansenPose    pose;
      JointVectors &p = pose.positions;
      p[Joint::E]     = {0., 0.};
      p[Joint::A]     = lengths.ea * unit_vector(lengths.ground_angle);
      p[Joint::B]     = p[Joint::A] + lengths.ab * unit_vector(theta2);
      p[Joint::C] =
        close_dyad(p[Joint::B], lengths.bc, p[Joint::E], lengths.ce, branches.c, "C", theta2);
      p[Joint::G] =
        close_dyad(p[Joint::B], lengths.bg, p[Joint::E], lengths.eg, branches.g, "G", theta2);
      p[Joint::D] =
        close_dyad(p[Joint::E], lengths.de, p[Joint::C], lengths.cd, branches.d, "D", theta2);
      p[Joint::F] =
        close_dyad(p[Joint::D], lengths.df, p[Joint::G], lengths.fg, branches.f, "F", theta2);
      p[Joint::H] =
        close_dyad(p[Joint::G], lengths.gh, p[Joint::F], lengths.fh, branches.h, "H", theta2);

      LinkAngles &a = pose.angles;
      a.theta1      = direction_angle(p[Joint::A] - p[Joint::E]);
      a.theta2      = direction_angle(p[Joint::B] - p[Joint::A]);
      a.theta3      = direction_angle(p[Joint::C] - p[Joint::B]);
      a.theta4      = direction_angle(p[Joint::G] - p[Joint::B]);
      a.theta5      = direction_angle(p[Joint::E] - p[Joint::C]);
      a.theta5p     = direction_angle(p[Joint::D] - p[Joint::E]);
      a.theta6      = direction_angle(p[Joint::E] - p[Joint::G]);
      a.theta7      = direction_angle(p[Joint::F] - p[Joint::D]);
      a.theta8      = direction_angle(p[Joint::G] - p[Joint::F]);
      a.theta8p     = direction_angle(p[Joint::H] - p[Joint::G]);
      return pose;
    }

    JointVectors joint_positions(const JansenLinkLengths &lengths,
                                 const double             theta2,
                                 const AssemblyBranches  &branches)
    {
      return solve_position(lengths, theta2, branches).positions;
    }

    std::array<double, 10> loop_closure_residuals(const JansenLinkLengths &lengths,
                                                  const JansenPose        &pose)
    {
      const LinkAngles  &a  = pose.angles;
      const PlanarVector r1 = lengths.ea * unit_vector(a.theta1);
      const PlanarVector r2 = lengths.ab * unit_vector(a.theta2);
      const PlanarVector r3 = lengths.bc * unit_vector(a.theta3);
      const PlanarVector r4 = lengths.bg * unit_vector(a.theta4);
      const PlanarVector r5 = lengths.ce * unit_vector(a.theta5);
      const PlanarVector r5p = lengths.de * unit_vector(a.theta5p);
      const PlanarVector r6  = lengths.eg * unit_vector(a.theta6);
      const PlanarVector r7  = lengths.df * unit_vector(a.theta7);
      const PlanarVector r8  = lengths.fg * unit_vector(a.theta8);
      const PlanarVector r8p = lengths.gh * unit_vector(a.theta8p);

      const PlanarVector loop1 = r1 + r2 + r3 + r5;
      const PlanarVector loop2 = r1 + r2 + r4 + r6;
      const PlanarVector loop3 = r6 + r5p + r7 + r8;
      const PlanarVector foot =
        (pose.positions[Joint::H] - pose.positions[Joint::E]) - (-1. * r6 + r8p);
      return {loop1.x,
              loop1.y,
              loop2.x,
              loop2.y,
              loop3.x,
              loop3.y,
              norm(r5 + r5p) - lengths.cd,
              norm(r8 + r8p) - lengths.fh,
              foot.x,
              foot.y};
    }
  } // namespace jansen
} // namespace compliant
