#include <mechanisms/jansen/jansen_finite_differences.h>

#include <array>
#include <cmath>
#include <stdexcept>

namespace compliant
{
  namespace jansen
  {
    namespace
    {
      // Quantities differentiated: the six link angles, then x_H and y_H.
      constexpr std::size_t n_quantities = 8;
      using Sample                       = std::array<double, n_quantities>;

      Sample sample(const JansenLinkLengths &lengths,
                    const double             theta2,
                    const AssemblyBranches  &branches)
      {
        const JansenPose   pose = solve_position(lengths, theta2, branches);
        const LinkAngles  &a    = pose.angles;
        const PlanarVector foot = pose.positions[Joint::H];
        return {a.theta3, a.theta4, a.theta5, a.theta6, a.theta7, a.theta8, foot.x, foot.y};
      }

      // Angle difference folded into (-pi, pi]: the angles live in [0, 2 pi)
      // and may wrap between neighbouring samples.
      double angle_difference(const double a, const double b)
      {
        return std::remainder(a - b, 2. * M_PI);
      }
    } // namespace

    FiniteDifferenceMotion differentiate_position_analysis(const JansenLinkLengths &lengths,
                                                           const double             theta2,
                                                           const double             omega2,
                                                           const double             step,
                                                           const AssemblyBranches  &branches)
    {
      if (!(std::isfinite(step) && step > 0.))
        throw std::invalid_argument(
          "differentiate_position_analysis: step must be a positive finite crank angle (rad)");

      const Sample centre = sample(lengths, theta2, branches);
      // Offsets from the centre sample at theta2 + k h, k = -2..2.
      std::array<Sample, 5> offset{};
      for (int k = -2; k <= 2; ++k)
        {
          const Sample s = sample(lengths, theta2 + k * step, branches);
          for (std::size_t q = 0; q < n_quantities; ++q)
            offset[k + 2][q] = q < 6 ? angle_difference(s[q], centre[q]) : s[q] - centre[q];
        }

      Sample first{}, second{};
      for (std::size_t q = 0; q < n_quantities; ++q)
        {
          const double m2 = offset[0][q], m1 = offset[1][q], p1 = offset[3][q],
                       p2 = offset[4][q];
          first[q]  = (-p2 + 8. * p1 - 8. * m1 + m2) / (12. * step);
          second[q] = (-p2 + 16. * p1 + 16. * m1 - m2) / (12. * step * step); // f0 = 0
          first[q] *= omega2;
          second[q] *= omega2 * omega2;
        }

      FiniteDifferenceMotion result;
      result.angular_velocities =
        {first[0], first[1], first[2], first[3], first[4], first[5]};
      result.angular_accelerations =
        {second[0], second[1], second[2], second[3], second[4], second[5]};
      result.foot_velocity     = {first[6], first[7]};
      result.foot_acceleration = {second[6], second[7]};
      return result;
    }
  } // namespace jansen
} // namespace compliant
