// Choice of the crank interval in which the flap mechanism works (the paper does not give it).
#pragma once

#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/position_analysis.h>

namespace compliant
{
  namespace four_bar
  {
    // Crank angle in (-pi, pi] on the given branch where the transmission angle is 90 deg and
    // |dth4/dth2| is the largest among such angles (best force transmission, and the least crank
    // rotation, hence the least flexure rotation at A and B, per degree of flap).
    // Throws std::domain_error if the transmission angle never reaches 90 deg.
    double crank_angle_with_right_transmission(const LinkLengths &lengths, AssemblyBranch branch);

    // Rocker excursion max th4 - min th4 while the crank moves through
    // [centre - sweep/2, centre + sweep/2] on the given branch (branch-tracked, so valid through
    // dead points). Throws std::domain_error if the chain cannot be closed inside the window.
    double rocker_sweep_over(const LinkLengths &lengths, AssemblyBranch branch, double crank_centre,
                             double crank_sweep, unsigned int n_samples = 400);

    // Crank sweep, centred on crank_centre, that makes the rocker sweep rocker_sweep, by
    // bisection to 1e-12 rad. Throws std::domain_error if no crank window around the centre
    // reaches that rocker sweep.
    double crank_sweep_for_rocker_sweep(const LinkLengths &lengths, AssemblyBranch branch,
                                        double crank_centre, double rocker_sweep);

    // Smallest |sin(th3 - th4)| over the window: zero means a dead or change point inside it.
    double min_collinearity_over(const LinkLengths &lengths, AssemblyBranch branch,
                                 double crank_start, double crank_end,
                                 unsigned int n_samples = 400);
  } // namespace four_bar
} // namespace compliant
