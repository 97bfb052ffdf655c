#include <mechanisms/four_bar/motor_ripple.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace four_bar
  {
    void DcMotor::check() const
    {
      const std::array<std::pair<const char *, double>, 3> values = {
        {{"motor no-load speed", no_load_speed},
         {"motor stall torque", stall_torque},
         {"motor reflected inertia", reflected_inertia}}};
      for (const auto &[name, value] : values)
        if (!(std::isfinite(value) && value > 0.))
          throw std::invalid_argument(std::string("four_bar: ") + name +
                                      " must be positive and finite, got " + std::to_string(value));
    }

    RippleResult simulate_motor_ripple(const DcMotor                          &motor,
                                       const std::function<MotorLoad(double)> &load,
                                       const double cycle_angle, const unsigned int n_cycles,
                                       const unsigned int steps_per_cycle)
    {
      motor.check();
      if (!(std::isfinite(cycle_angle) && cycle_angle > 0.) || n_cycles < 2 || steps_per_cycle < 16)
        throw std::invalid_argument("four_bar: ripple simulation needs a positive cycle angle, "
                                    "at least 2 cycles and 16 steps per cycle");

      // State (phi, W). Time step from the nominal speed, but at most half the motor's
      // mechanical time constant J_m W_0 / T_stall: explicit RK4 is unstable beyond ~2.8 of it.
      const double time_constant =
        motor.reflected_inertia * motor.no_load_speed / motor.stall_torque;
      const double dt =
        std::min(cycle_angle / motor.no_load_speed / steps_per_cycle, 0.5 * time_constant);
      const auto rate = [&](const std::array<double, 2> &y) -> std::array<double, 2> {
        const MotorLoad L = load(y[0]);
        const double    acceleration =
          (motor.torque(y[1]) - 0.5 * L.inertia_derivative * y[1] * y[1] - L.generalized_force) /
          (motor.reflected_inertia + L.inertia);
        return {y[1], acceleration};
      };

      std::array<double, 2> y = {0., motor.no_load_speed};
      RippleResult          result{0., y[1], y[1], 0., 0.};
      double                speed_sum = 0., min_force = 0., max_force = 0.;
      unsigned int          n_last           = 0;
      double                last_cycle_start = (n_cycles - 1) * cycle_angle;
      for (unsigned long step = 0; y[0] < n_cycles * cycle_angle; ++step)
        {
          const auto k1 = rate(y);
          const auto k2 = rate({y[0] + 0.5 * dt * k1[0], y[1] + 0.5 * dt * k1[1]});
          const auto k3 = rate({y[0] + 0.5 * dt * k2[0], y[1] + 0.5 * dt * k2[1]});
          const auto k4 = rate({y[0] + dt * k3[0], y[1] + dt * k3[1]});
          for (unsigned int i = 0; i < 2; ++i)
            y[i] += dt / 6. * (k1[i] + 2. * k2[i] + 2. * k3[i] + k4[i]);
          if (!std::isfinite(y[1]) || y[1] <= 0.)
            throw std::domain_error("four_bar: the motor stalls under this load (speed reached " +
                                    std::to_string(y[1]) + " rad/s)");
          if (y[0] < 0. || step > 100000000ul)
            throw std::domain_error("four_bar: ripple simulation did not complete its cycles");
          if (y[0] >= last_cycle_start)
            {
              const double force = load(y[0]).generalized_force;
              if (n_last == 0)
                {
                  result.min_speed = result.max_speed = y[1];
                  min_force = max_force = force;
                }
              result.min_speed = std::min(result.min_speed, y[1]);
              result.max_speed = std::max(result.max_speed, y[1]);
              min_force        = std::min(min_force, force);
              max_force        = std::max(max_force, force);
              speed_sum += y[1];
              ++n_last;
            }
        }
      result.mean_speed = speed_sum / std::max(n_last, 1u);
      result.ripple     = result.max_speed - result.min_speed;
      result.quasi_static_ripple =
        motor.no_load_speed * (max_force - min_force) / motor.stall_torque;
      return result;
    }
  } // namespace four_bar
} // namespace compliant
