// Independent check of the analytic velocity and acceleration analysis:
// differentiate the position analysis numerically in the crank angle. For a
// constant crank speed omega2, d theta_k/dt = omega2 d theta_k/d theta2 and
// d^2 theta_k/dt^2 = omega2^2 d^2 theta_k/d theta2^2 (likewise for the foot).
#pragma once

#include <mechanisms/jansen/jansen_motion_analysis.h>
#include <mechanisms/jansen/jansen_position_analysis.h>

namespace compliant
{
  namespace jansen
  {
    struct FiniteDifferenceMotion
    {
      LinkRates    angular_velocities;
      LinkRates    angular_accelerations;
      PlanarVector foot_velocity;
      PlanarVector foot_acceleration;
    };

    // Fourth-order central differences (five-point stencils, crank-angle step
    // h in radians): first derivative (-f2 + 8 f1 - 8 f-1 + f-2) / (12 h),
    // truncation h^4 f^(5) / 30; second derivative
    // (-f2 + 16 f1 - 30 f0 + 16 f-1 - f-2) / (12 h^2), truncation h^4 f^(6) / 90.
    // With h = 1e-3 rad the round-off of the second derivative is
    // ~1e-16 / h^2 = 1e-10 relative and, for the paper's leg, the truncation
    // stays below that except in the swing near theta2 = 190 deg, where the
    // dyad at G comes closest to a dead point and the accelerations are
    // matched only to ~2e-7 relative (velocities to ~1e-9).
    // Throws std::invalid_argument for a non-positive or non-finite step.
    FiniteDifferenceMotion differentiate_position_analysis(
      const JansenLinkLengths &lengths,
      const double             theta2,
      const double             omega2,
      const double             step     = 1e-3,
      const AssemblyBranches  &branches = AssemblyBranches());
  } // namespace jansen
} // namespace compliant
