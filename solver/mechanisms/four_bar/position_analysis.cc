#include <mechanisms/four_bar/position_analysis.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace four_bar
  {
    double wrap_angle(const double angle)
    {
      const double wrapped = std::remainder(angle, 2. * M_PI); // in [-pi, pi]
      return wrapped <= -M_PI ? wrapped + 2. * M_PI : wrapped;
    }

    AssemblyBranch other_branch(const AssemblyBranch branch)
    {
      return branch == AssemblyBranch::plus ? AssemblyBranch::minus : AssemblyBranch::plus;
    }

    const char *to_string(const AssemblyBranch branch)
    {
      return branch == AssemblyBranch::plus ? "plus" : "minus";
    }

    FreudensteinCoefficients freudenstein_coefficients(const LinkLengths &lengths,
                                                       const double       crank_angle)
    {
      const double l1 = lengths.ground, l2 = lengths.crank, l3 = lengths.coupler,
                   l4 = lengths.rocker;
      FreudensteinCoefficients k;
      k.k1 = -2. * l2 * l4 * std::sin(crank_angle);                                        // E6
      k.k2 = 2. * l4 * (l1 - l2 * std::cos(crank_angle));                                  // E7
      k.k3 = l1 * l1 + l2 * l2 - l3 * l3 + l4 * l4 - 2. * l1 * l2 * std::cos(crank_angle); // E8
      k.discriminant = k.k1 * k.k1 + k.k2 * k.k2 - k.k3 * k.k3;
      return k;
    }

    std::array<double, 2> rocker_angle_candidates(const LinkLengths &lengths,
                                                  const double       crank_angle)
    {
      check_link_lengths(lengths);
      if (!std::isfinite(crank_angle))
        throw std::invalid_argument("four_bar: crank angle must be finite");

      const FreudensteinCoefficients k     = freudenstein_coefficients(lengths, crank_angle);
      const double                   scale = k.k1 * k.k1 + k.k2 * k.k2 + k.k3 * k.k3;
      if (k.discriminant < -singular_discriminant_tolerance * scale)
        {
          std::ostringstream message;
          message << "four_bar: the chain cannot be closed at crank angle " << crank_angle
                  << " rad (Freudenstein discriminant " << k.discriminant / scale
                  << " relative, must be >= 0)";
          throw std::domain_error(message.str());
        }
      const double root = std::sqrt(std::max(k.discriminant, 0.));

      // Eq. E12: a t^2 + 2 k1 t + c = 0 with a = k3 - k2, c = k3 + k2. Each root of Eq. E13 has
      // two equivalent forms, t = (-k1 +- root)/a = c/(-k1 -+ root) (their product is a c); the
      // one with the larger denominator is used, which avoids both cancellation in the
      // numerator and the 0/0 of the second form at the fold of a change-point linkage
      // (k1 = c = root = 0 there). th4 = 2 atan2(numerator, denominator) needs no special case
      // for a = 0 (t infinite, th4 = pi).
      const double a = k.k3 - k.k2, c = k.k3 + k.k2;
      const double numerator_plus = -k.k1 + root, numerator_minus = -k.k1 - root;
      const double th4_plus  = std::abs(a) >= std::abs(numerator_minus) ?
                                 2. * std::atan2(numerator_plus, a) :
                                 2. * std::atan2(c, numerator_minus);
      const double th4_minus = std::abs(a) >= std::abs(numerator_plus) ?
                                 2. * std::atan2(numerator_minus, a) :
                                 2. * std::atan2(c, numerator_plus);
      return {wrap_angle(th4_plus), wrap_angle(th4_minus)};
    }

    double coupler_angle_from(const LinkLengths &lengths, const double crank_angle,
                              const double rocker_angle)
    {
      // E3, E4: l3 e^{i th3} = l1 + l4 e^{i th4} - l2 e^{i th2}.
      return std::atan2(lengths.rocker * std::sin(rocker_angle) -
                          lengths.crank * std::sin(crank_angle),
                        lengths.ground + lengths.rocker * std::cos(rocker_angle) -
                          lengths.crank * std::cos(crank_angle));
    }

    Pose solve_pose(const LinkLengths &lengths, const double crank_angle,
                    const AssemblyBranch branch)
    {
      const auto   candidates = rocker_angle_candidates(lengths, crank_angle);
      const double th4        = candidates[branch == AssemblyBranch::plus ? 0 : 1];
      return {crank_angle, coupler_angle_from(lengths, crank_angle, th4), th4, branch};
    }

    double closure_residual(const LinkLengths &lengths, const Pose &pose)
    {
      const double x = lengths.crank * std::cos(pose.crank_angle) +
                       lengths.coupler * std::cos(pose.coupler_angle) - lengths.ground -
                       lengths.rocker * std::cos(pose.rocker_angle);
      const double y = lengths.crank * std::sin(pose.crank_angle) +
                       lengths.coupler * std::sin(pose.coupler_angle) -
                       lengths.rocker * std::sin(pose.rocker_angle);
      return std::hypot(x, y);
    }

    JointPositions joint_positions(const LinkLengths &lengths, const Pose &pose)
    {
      JointPositions p;
      p.a = {0., 0.};
      p.d = {lengths.ground, 0.};
      p.b = {lengths.crank * std::cos(pose.crank_angle),
             lengths.crank * std::sin(pose.crank_angle)};
      p.c = {lengths.ground + lengths.rocker * std::cos(pose.rocker_angle),
             lengths.rocker * std::sin(pose.rocker_angle)};
      return p;
    }
  } // namespace four_bar
} // namespace compliant
