#include <mechanisms/four_bar/branch_tracker.h>

#include <cmath>

namespace compliant
{
  namespace four_bar
  {
    double unwrap_near(const double angle, const double reference)
    {
      return angle + 2. * M_PI * std::round((reference - angle) / (2. * M_PI));
    }

    BranchTracker::BranchTracker(const LinkLengths &lengths_, const double initial_crank_angle,
                                 const AssemblyBranch initial_branch)
        : lengths(lengths_)
        , current(solve_pose(lengths_, initial_crank_angle, initial_branch))
    {
    }

    Pose BranchTracker::peek(const double crank_angle) const
    {
      // Linear extrapolation from the last two poses; constant from a single one.
      double predicted_rocker  = current.rocker_angle;
      double predicted_coupler = current.coupler_angle;
      if (previous && previous->crank_angle != current.crank_angle)
        {
          const double ratio =
            (crank_angle - current.crank_angle) / (current.crank_angle - previous->crank_angle);
          predicted_rocker += ratio * (current.rocker_angle - previous->rocker_angle);
          predicted_coupler += ratio * (current.coupler_angle - previous->coupler_angle);
        }

      const auto   candidates     = rocker_angle_candidates(lengths, crank_angle);
      const double plus           = unwrap_near(candidates[0], predicted_rocker);
      const double minus          = unwrap_near(candidates[1], predicted_rocker);
      const double distance_plus  = std::abs(plus - predicted_rocker);
      const double distance_minus = std::abs(minus - predicted_rocker);

      AssemblyBranch branch        = current.branch;
      const double   tie_tolerance = 1e-12 * (1. + std::abs(predicted_rocker));
      if (distance_plus + tie_tolerance < distance_minus)
        branch = AssemblyBranch::plus;
      else if (distance_minus + tie_tolerance < distance_plus)
        branch = AssemblyBranch::minus;

      const double rocker = branch == AssemblyBranch::plus ? plus : minus;
      const double coupler =
        unwrap_near(coupler_angle_from(lengths, crank_angle, rocker), predicted_coupler);
      return {crank_angle, coupler, rocker, branch};
    }

    const Pose &BranchTracker::advance(const double crank_angle)
    {
      const Pose next = peek(crank_angle);
      if (next.branch != current.branch)
        ++switches;
      previous = current;
      current  = next;
      return current;
    }
  } // namespace four_bar
} // namespace compliant
