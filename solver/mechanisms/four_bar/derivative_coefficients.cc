#include <mechanisms/four_bar/derivative_coefficients.h>

#include <cmath>
#include <limits>

namespace compliant
{
  namespace four_bar
  {
    DerivativeCoefficients derivative_coefficients(const LinkLengths &lengths, const Pose &pose)
    {
      const double l2 = lengths.crank, l3 = lengths.coupler, l4 = lengths.rocker;
      const double th2 = pose.crank_angle, th3 = pose.coupler_angle, th4 = pose.rocker_angle;
      const double sin34 = std::sin(th3 - th4);

      DerivativeCoefficients h;
      if (std::abs(sin34) < collinear_tolerance)
        {
          const double nan = std::numeric_limits<double>::quiet_NaN();
          h                = {nan, nan, nan, nan, true};
          return h;
        }
      h.singular = false;

      // d/dth2 of Eq. 2: i l2 e^{i th2} + i l3 h3 e^{i th3} - i l4 h4 e^{i th4} = 0; its
      // components normal to the rocker and to the coupler give (E17, E18):
      h.coupler_velocity = l2 * std::sin(th4 - th2) / (l3 * sin34);
      h.rocker_velocity  = l2 * std::sin(th3 - th2) / (l4 * sin34);
      const double h3 = h.coupler_velocity, h4 = h.rocker_velocity;

      // Second derivative: -l2 e^{i th2} - l3 h3^2 e^{i th3} + l4 h4^2 e^{i th4}
      //                    + i (l3 h3' e^{i th3} - l4 h4' e^{i th4}) = 0,
      // projected on the rocker direction (eliminates h4') and on the coupler (eliminates h3').
      h.coupler_acceleration =
        (-l2 * std::cos(th2 - th4) - l3 * h3 * h3 * std::cos(th3 - th4) + l4 * h4 * h4) /
        (l3 * sin34);
      h.rocker_acceleration =
        (l2 * std::cos(th2 - th3) + l3 * h3 * h3 - l4 * h4 * h4 * std::cos(th4 - th3)) /
        (l4 * std::sin(th4 - th3));
      return h;
    }

    double transmission_angle(const Pose &pose)
    {
      // Angle between the vectors C->B and C->D, i.e. between directions th3 and th4.
      return std::abs(wrap_angle(pose.rocker_angle - pose.coupler_angle));
    }

    double transmission_deviation(const Pose &pose)
    {
      return std::abs(0.5 * M_PI - transmission_angle(pose));
    }
  } // namespace four_bar
} // namespace compliant
