// Pseudo-rigid-body model (PRBM) of the one-piece compliant four-bar: each flexure at A, B, C, D
// becomes a pin with a torsional spring (flap paper Eq. 4-8, 12; Howell, Compliant Mechanisms,
// Wiley 2001, sec. 5.2, small-length flexural pivot).
#pragma once

#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <array>

namespace compliant
{
  namespace four_bar
  {
    // Small-length flexural pivot K = E I / l_k with I = b h^3 / 12 (paper Eq. 4 and E38,
    // Howell eq. 5.1): h is the thickness in the bending direction, b the width.
    // Throws std::invalid_argument naming the parameter if one is not positive and finite.
    double flexural_pivot_stiffness(double youngs_modulus, double width, double thickness,
                                    double flexure_length);

    // Springs at the joints A (ground-crank), B (crank-coupler), C (coupler-rocker) and
    // D (rocker-ground), unloaded in the rest pose (the as-printed shape: th20, th30, th40).
    struct PrbmSprings
    {
      std::array<double, 4> stiffness; // K1..K4 [N m/rad] at A, B, C, D
      Pose                  rest;
    };

    // Relative rotations across the four flexures measured from the rest pose:
    // A: th2 - th20, B: (th3 - th30) - (th2 - th20), C: (th4 - th40) - (th3 - th30),
    // D: th4 - th40. Poses must be unwrapped consistently with the rest pose.
    std::array<double, 4> flexure_rotations(const PrbmSprings &springs, const Pose &pose);

    // Spring moments T_K1..T_K4 of Eq. 5-8 (the moment each spring exerts, -K times rotation).
    std::array<double, 4> spring_moments(const PrbmSprings &springs, const Pose &pose);

    // U = sum 1/2 K_i rotation_i^2: elastic energy stored in the four flexures [J].
    double spring_energy(const PrbmSprings &springs, const Pose &pose);

    // Input torque on the crank that holds the mechanism in static equilibrium against the
    // springs, by virtual work (Eq. 10-12):
    // T_in = K1 r_A + K2 r_B (h3 - 1) + K3 r_C (h4 - h3) + K4 r_D h4 = dU/dth2.
    double input_torque_virtual_work(const PrbmSprings &springs, const Pose &pose,
                                     const DerivativeCoefficients &coefficients);
  } // namespace four_bar
} // namespace compliant
