// Follows one continuous motion of the four-bar along a crank sweep, choosing at every step
// the root of Eq. E13 that continues the previous steps.
//
// Why a tracker: the two roots of Eq. E13 are two assembly branches. In a change-point linkage
// (s + l = p + q, as the flap's 10 + 65 = 60 + 15) they meet at the folded position, where the
// discriminant is zero and the velocity coefficients are 0/0. There the smooth motion (the one
// a mechanism with inertia follows: any other would need an infinite acceleration, i.e. a jump
// in rocker velocity) passes from one root label to the other. The tracker predicts th4 and th3
// by linear extrapolation from the last two accepted poses (no derivatives, which are undefined
// at the change point) and takes the candidate nearest to the prediction. When both candidates
// are equally near (only possible when they coincide, or at the first step after a start exactly
// on a change point) it keeps the current branch label. Angles are unwrapped: they vary
// continuously and may leave (-pi, pi]. The crank step must be small against the curvature of
// th4(th2): a few degrees or less.
#pragma once

#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <optional>

namespace compliant
{
  namespace four_bar
  {
    class BranchTracker
    {
    public:
      BranchTracker(const LinkLengths &lengths, double initial_crank_angle,
                    AssemblyBranch initial_branch);

      // Last accepted pose.
      const Pose &pose() const { return current; }

      // Pose at crank_angle continuous with the accepted history, without accepting it.
      Pose peek(double crank_angle) const;

      // Accepts and returns the pose at crank_angle.
      const Pose &advance(double crank_angle);

      // How many times the root label of Eq. E13 changed along the accepted poses.
      unsigned int n_branch_switches() const { return switches; }

    private:
      LinkLengths         lengths;
      Pose                current;
      std::optional<Pose> previous;
      unsigned int        switches = 0;
    };

    // Unwraps angle by multiples of 2 pi to the value nearest to reference.
    double unwrap_near(double angle, double reference);
  } // namespace four_bar
} // namespace compliant
