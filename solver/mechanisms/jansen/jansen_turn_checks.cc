#include <mechanisms/jansen/jansen_turn_checks.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace compliant
{
  namespace jansen
  {
    TurnChecks check_crank_turn(const JansenLinkLengths &lengths,
                                const unsigned int       n_steps,
                                const AssemblyBranches  &branches)
    {
      if (n_steps < 1)
        throw std::invalid_argument("check_crank_turn: n_steps must be at least 1, got " +
                                    std::to_string(n_steps));
      using J                                                      = Joint;
      const std::vector<std::tuple<Joint, Joint, double>> links = {
        {J::E, J::A, lengths.ea}, {J::A, J::B, lengths.ab}, {J::B, J::C, lengths.bc},
        {J::B, J::G, lengths.bg}, {J::C, J::E, lengths.ce}, {J::D, J::E, lengths.de},
        {J::C, J::D, lengths.cd}, {J::E, J::G, lengths.eg}, {J::D, J::F, lengths.df},
        {J::F, J::G, lengths.fg}, {J::G, J::H, lengths.gh}, {J::F, J::H, lengths.fh}};
      // Free joint of each dyad and its two centres, as assembled.
      const std::vector<std::tuple<Joint, Joint, Joint>> dyads = {{J::C, J::B, J::E},
                                                                  {J::G, J::B, J::E},
                                                                  {J::D, J::E, J::C},
                                                                  {J::F, J::D, J::G},
                                                                  {J::H, J::G, J::F}};
      TurnChecks checks;
      for (unsigned int i = 0; i < n_steps; ++i)
        {
          const double     theta2 = 2. * M_PI * i / n_steps;
          const JansenPose pose   = solve_position(lengths, theta2, branches);
          for (const double r : loop_closure_residuals(lengths, pose))
            checks.max_loop_residual = std::max(checks.max_loop_residual, std::abs(r));
          const JointVectors &p = pose.positions;
          for (const auto &[from, to, length] : links)
            checks.max_length_error =
              std::max(checks.max_length_error, std::abs(norm(p[to] - p[from]) - length));
          for (const auto &[joint, first, second] : dyads)
            {
              const PlanarVector u = p[first] - p[joint], v = p[second] - p[joint];
              const double       s = std::abs(cross(u, v)) / (norm(u) * norm(v));
              if (s < checks.min_dyad_sine)
                {
                  checks.min_dyad_sine           = s;
                  checks.theta2_of_min_dyad_sine = theta2;
                  checks.joint_of_min_dyad_sine  = joint_name(joint)[0];
                }
            }
        }
      return checks;
    }
  } // namespace jansen
} // namespace compliant
