// Velocity and acceleration coefficients of the four-bar (kinematic influence coefficients):
// h3 = dth3/dth2, h4 = dth4/dth2 and their derivatives with respect to the crank angle,
// from the first and second derivative of the loop closure Eq. 2. The first derivatives are
// the paper's Eq. E17/E18 (its S1, S2) renamed to the Table 1 numbering; E15 in the paper has
// the right-hand side [-l1 cos th, l1 sin th] where differentiation gives [-l1 sin th, l1 cos th]
// (a typo that E17/E18 do not inherit).
// Angular velocities and accelerations follow as w3 = h3 w2, a3 = h3 a2 + h3' w2^2 (same for 4).
#pragma once

#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/position_analysis.h>

namespace compliant
{
  namespace four_bar
  {
    struct DerivativeCoefficients
    {
      double coupler_velocity;     // h3  = dth3/dth2
      double rocker_velocity;      // h4  = dth4/dth2
      double coupler_acceleration; // h3' = d2th3/dth2^2
      double rocker_acceleration;  // h4' = d2th4/dth2^2
      // True where coupler and rocker are collinear (sin(th3 - th4) = 0): the coefficients are
      // undefined there (0/0 at the flap's change point, a locked toggle elsewhere) and set to NaN.
      bool singular;
    };

    // |sin(th3 - th4)| below this counts as collinear coupler and rocker.
    constexpr double collinear_tolerance = 1e-12;

    DerivativeCoefficients derivative_coefficients(const LinkLengths &lengths, const Pose &pose);

    // Transmission angle mu in [0, pi]: the angle at C between the coupler and the rocker
    // (Norton sec. 4.10); force transmission is poor when mu is far from pi/2.
    double transmission_angle(const Pose &pose);

    // Deviation |pi/2 - mu|: zero is ideal; textbooks ask for mu within [40, 140] deg.
    double transmission_deviation(const Pose &pose);
  } // namespace four_bar
} // namespace compliant
