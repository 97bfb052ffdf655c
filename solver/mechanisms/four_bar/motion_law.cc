#include <mechanisms/four_bar/motion_law.h>

#include <cmath>
#include <stdexcept>

namespace compliant
{
  namespace four_bar
  {
    void MotionLaw::check() const
    {
      if (!std::isfinite(start_angle))
        throw std::invalid_argument("four_bar: motion law start angle must be finite");
      if (kind == MotionKind::harmonic_oscillation && !(std::isfinite(sweep) && sweep > 0.))
        throw std::invalid_argument("four_bar: crank sweep of the oscillation must be positive");
    }

    CrankState MotionLaw::at(const double motor_angle, const double motor_speed) const
    {
      CrankState state;
      if (kind == MotionKind::full_rotation)
        {
          state.angle                  = start_angle + motor_angle;
          state.drive_ratio            = 1.;
          state.drive_ratio_derivative = 0.;
        }
      else
        {
          const double amplitude       = 0.5 * sweep;
          state.angle                  = start_angle + amplitude * (1. - std::cos(motor_angle));
          state.drive_ratio            = amplitude * std::sin(motor_angle);
          state.drive_ratio_derivative = amplitude * std::cos(motor_angle);
        }
      // Constant motor speed: dth2/dt = s w, d2th2/dt2 = s' w^2.
      state.velocity     = state.drive_ratio * motor_speed;
      state.acceleration = state.drive_ratio_derivative * motor_speed * motor_speed;
      return state;
    }
  } // namespace four_bar
} // namespace compliant
