// Position analysis of the four-bar by the Freudenstein equation with the half-angle
// substitution t = tan(theta4 / 2) (flap paper, seed 000, Eq. E5-E13; Norton, Design of
// Machinery, sec. 4.5). Loop closure (Eq. 2): l2 e^{i th2} + l3 e^{i th3} = l1 + l4 e^{i th4}.
// Angles in radians, measured counter-clockwise from the ground line AD.
#pragma once

#include <mechanisms/four_bar/link_lengths.h>

#include <array>

namespace compliant
{
  namespace four_bar
  {
    // Sign in front of the square root in Eq. E13, t = (-k1 +- sqrt(k1^2 + k2^2 - k3^2))/(k3 - k2).
    // For the flap linkage, minus puts C above the ground line (0 <= th4 <= 116.4 deg) and
    // plus below it; for any linkage sin(th4 - th3) keeps one sign on each branch away from
    // change points (checked by the unit tests).
    enum class AssemblyBranch
    {
      plus,
      minus
    };

    // Angle mapped into (-pi, pi].
    double wrap_angle(double angle);

    AssemblyBranch other_branch(AssemblyBranch branch);
    const char    *to_string(AssemblyBranch branch);

    // Eq. E6-E8 and the discriminant of Eq. E12: k1 sin th4 + k2 cos th4 + k3 = 0.
    struct FreudensteinCoefficients
    {
      double k1;
      double k2;
      double k3;
      double discriminant; // k1^2 + k2^2 - k3^2; zero at a dead or change point
    };

    FreudensteinCoefficients freudenstein_coefficients(const LinkLengths &lengths,
                                                       double             crank_angle);

    // Joint angles of one configuration. Rocker and coupler angles may be unwrapped
    // (outside (-pi, pi]) when they come from a branch tracker.
    struct Pose
    {
      double         crank_angle;   // th2
      double         coupler_angle; // th3
      double         rocker_angle;  // th4
      AssemblyBranch branch;
    };

    // Relative discriminant below which (in magnitude) a position is treated as a dead or
    // change point: round-off makes an exact zero come out as +-1e-16 of k1^2 + k2^2 + k3^2.
    constexpr double singular_discriminant_tolerance = 1e-12;

    // Both rocker angles th4 (in (-pi, pi]) for the given crank angle: [plus, minus].
    // A discriminant within the tolerance of zero is clamped to zero (the two coincide);
    // a clearly negative one throws std::domain_error (the chain cannot be closed).
    std::array<double, 2> rocker_angle_candidates(const LinkLengths &lengths, double crank_angle);

    // Coupler angle th3 from th2 and th4 by Eq. E3/E4 (atan2 of the two components).
    double coupler_angle_from(const LinkLengths &lengths, double crank_angle, double rocker_angle);

    // Pose on the requested branch; throws std::domain_error if the chain cannot be closed
    // and std::invalid_argument for bad lengths.
    Pose solve_pose(const LinkLengths &lengths, double crank_angle, AssemblyBranch branch);

    // |l2 e^{i th2} + l3 e^{i th3} - l1 - l4 e^{i th4}|: loop closure residual (a length).
    double closure_residual(const LinkLengths &lengths, const Pose &pose);

    // Joint positions (x, y) with A at the origin and D at (l1, 0).
    struct JointPositions
    {
      std::array<double, 2> a, b, c, d;
    };
    JointPositions joint_positions(const LinkLengths &lengths, const Pose &pose);
  } // namespace four_bar
} // namespace compliant
