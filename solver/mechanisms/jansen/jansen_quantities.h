// The kinematic quantities the seed paper prints at its ground-contact pose,
// as one indexed list so that this work, finite differences and the paper can
// be tabulated side by side.
#pragma once

#include <mechanisms/jansen/jansen_finite_differences.h>
#include <mechanisms/jansen/jansen_motion_analysis.h>
#include <mechanisms/jansen/jansen_position_analysis.h>

#include <array>
#include <cstddef>
#include <string>

namespace compliant
{
  namespace jansen
  {
    enum class Quantity : std::size_t
    {
      theta2, theta3, theta4, theta5, theta5p, theta6, theta7, theta8, theta8p,
      omega3, omega4, omega5, omega6, omega7, omega8,
      foot_velocity_x, foot_velocity_y, foot_speed,
      alpha3, alpha4, alpha5, alpha6, alpha7, alpha8,
      foot_acceleration_x, foot_acceleration_y, foot_acceleration_magnitude,
      n_quantities
    };

    constexpr std::size_t n_quantities = static_cast<std::size_t>(Quantity::n_quantities);

    // Angles in degrees in [0, 360), rates in rad/s and rad/s^2, foot in the
    // length unit (mm) per s or s^2.
    using QuantityValues = std::array<double, n_quantities>;

    std::string quantity_label(const Quantity quantity); // e.g. "omega5 (=omega5')"
    std::string quantity_unit(const Quantity quantity);  // e.g. "rad/s"
    bool        is_angle(const Quantity quantity);

    QuantityValues tabulate(const LinkAngles &angles, const JansenMotion &motion);

    // Angles from the pose, rates from finite differences of the position analysis.
    QuantityValues tabulate(const LinkAngles &angles, const FiniteDifferenceMotion &motion);
  } // namespace jansen
} // namespace compliant
