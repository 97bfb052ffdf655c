// Exact assembly and toggle analysis of a four-bar driven by its crank AB, without stepping.
//
// Why not a stepped motion: near a toggle the two assemblies (C on either side of the diagonal BD)
// are only 2 mu apart, mu the transmission angle; a tracker that picks the root nearest to an
// extrapolation hops from one to the other unnoticed. Here the assembly is a sign, and it can only
// change where the diagonal s = |BD| reaches |l3 - l4| or l3 + l4 (mu = 0 or 180 degrees). Over a
// crank sweep s^2 = l1^2 + l2^2 - 2 l1 l2 cos(th2) has its extremes at the sweep's ends or where
// th2 passes 0 or pi, so the closest approach to a toggle is found in closed form.
// Library frame: A at the origin, D at (l1, 0), angles counter-clockwise (see position_analysis.h).
#pragma once

#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <array>
#include <vector>

namespace compliant
{
  namespace four_bar
  {
    // +1 if C lies to the left of the directed diagonal B -> D, -1 to the right, 0 on it (a toggle).
    // Each sign is one assembly of the crank-driven chain; it cannot change without a toggle.
    int assembly_sign(const std::array<double, 2> &b, const std::array<double, 2> &c,
                      const std::array<double, 2> &d);

    // Joints at crank angle th2 on the assembly with the given sign (+1 or -1), built directly
    // from the two circles about B and D. Throws std::domain_error if the chain cannot be closed.
    JointPositions assemble(const LinkLengths &lengths, double crank_angle, int sign);

    // Transmission angle (angle BCD, 0..pi) for a diagonal s = |BD|, clamped to [0, pi] outside
    // the range in which the chain closes.
    double transmission_angle_for_diagonal(const LinkLengths &lengths, double diagonal);

    // Crank angles (in (-pi, pi]) where the chain reaches a toggle, mu = 0 or pi (0 to 4 of them).
    std::vector<double> toggle_crank_angles(const LinkLengths &lengths);

    // What a crank sweep from th_start through a signed travel (|travel| <= 2 pi) passes.
    struct CrankSweep
    {
      double mu_min = 0, mu_max = 0; // transmission angle over the sweep (radians)
      // Closest approach to a toggle: min(mu_min, pi - mu_max), zero or less if one is reached.
      double transmission_margin = 0;
      // Crank rotation from the sweep to the nearest toggle outside it (radians), infinite when the
      // crank turns fully without one; zero when a toggle lies inside the sweep.
      double crank_margin = 0;
      bool   toggle_inside      = false;
      double toggle_travel      = 0; // unsigned crank travel from th_start to the first toggle inside
      bool   closes_everywhere  = true; // false if the chain cannot be closed somewhere in the sweep
    };
    CrankSweep analyse_crank_sweep(const LinkLengths &lengths, double crank_start, double travel);
  } // namespace four_bar
} // namespace compliant
