// Mass properties of the moving links and the one-degree-of-freedom Lagrangian terms in the crank
// angle th2 (flap paper Eq. 3 and E19-E37, rewritten in the Table 1 numbering):
//   kinetic energy    E_kin = 1/2 J(th2) w2^2,
//   equation of motion J(th2) a2 + 1/2 J'(th2) w2^2 + dV/dth2 = T_crank,
// where V is the gravity potential plus, for the compliant mechanism, the spring energy.
// The paper's E37 prints [...] th' where the Lagrangian gives [...] th'^2 (as written here);
// its E19-E26 number the moving links 1..3 and the crank length l1, unlike Table 1.
#pragma once

#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/link_lengths.h>
#include <mechanisms/four_bar/position_analysis.h>

#include <array>

namespace compliant
{
  namespace four_bar
  {
    struct LinkMass
    {
      double mass;           // [kg]
      double centre_inertia; // mass moment of inertia about the centre of mass [kg m^2]
      // Distance of the centre of mass from the link's first joint (A for the crank, B for the
      // coupler, D for the rocker) along the link line [m]; the paper gives none: mid-link.
      double centre_offset;
    };

    struct MovingLinkMasses
    {
      LinkMass crank;
      LinkMass coupler;
      LinkMass rocker;
    };

    // Throws std::invalid_argument naming the link if a mass or inertia is negative or not
    // finite or an offset is not finite.
    void check_masses(const MovingLinkMasses &masses);

    struct InertiaTerms
    {
      double value;      // J(th2) [kg m^2]: the whole mechanism reduced to the crank
      double derivative; // dJ/dth2
    };

    InertiaTerms generalized_inertia(const LinkLengths &lengths, const MovingLinkMasses &masses,
                                     const Pose &pose, const DerivativeCoefficients &h);

    // dV_g/dth2 for uniform gravity g = (gx, gy) [m/s^2] in the frame of the ground line
    // (x along AD): the torque the crank must supply to hold the links against their weight.
    double gravity_torque(const LinkLengths &lengths, const MovingLinkMasses &masses,
                          const Pose &pose, const DerivativeCoefficients &h,
                          const std::array<double, 2> &gravity);

    // Gravity potential V_g = -sum m g . r_centre [J], zero with every centre at A's level.
    double gravity_potential(const LinkLengths &lengths, const MovingLinkMasses &masses,
                             const Pose &pose, const std::array<double, 2> &gravity);

    // Centres of mass (x, y) of crank, coupler and rocker.
    std::array<std::array<double, 2>, 3>
    mass_centres(const LinkLengths &lengths, const MovingLinkMasses &masses, const Pose &pose);
  } // namespace four_bar
} // namespace compliant
