// Speed ripple of a DC motor driving the mechanism: the flap paper reports about 0.001 rpm but
// gives no motor data, so the motor is a stated assumption: a linear torque-speed line
// T_m = T_stall (1 - W/W_0) with a reflected rotor-and-gearbox inertia J_m. The motor angle phi
// obeys (Lagrange, with the mechanism reduced to the motor shaft)
//   (J_m + J_phi) phi'' + 1/2 dJ_phi/dphi phi'^2 + Q_phi = T_m(phi'),
// integrated with classical Runge-Kutta (RK4) until the transient has died out.
#pragma once

#include <functional>

namespace compliant
{
  namespace four_bar
  {
    struct DcMotor
    {
      double no_load_speed;     // W_0 [rad/s]
      double stall_torque;      // T_stall [N m] at the output shaft
      double reflected_inertia; // J_m [kg m^2] at the output shaft

      // Throws std::invalid_argument naming the parameter if one is not positive and finite.
      void   check() const;
      double torque(double speed) const { return stall_torque * (1. - speed / no_load_speed); }
    };

    // Load seen by the motor at motor angle phi: J_phi, dJ_phi/dphi, Q_phi.
    struct MotorLoad
    {
      double inertia;
      double inertia_derivative;
      double generalized_force;
    };

    struct RippleResult
    {
      double mean_speed; // over the last cycle [rad/s]
      double min_speed;
      double max_speed;
      double ripple; // max - min over the last cycle [rad/s]
      // Quasi-static estimate: the motor follows its torque-speed line without inertia,
      // ripple = W_0 (max Q_phi - min Q_phi) / T_stall (exact as J_m -> 0 and for small ripple).
      double quasi_static_ripple;
    };

    // Integrates from phi = 0, phi' = W_0 over n_cycles cycles of cycle_angle (2 pi per motor
    // turn), at least steps_per_cycle RK4 steps each (more if the motor's time constant
    // J_m W_0 / T_stall demands), and measures the last cycle.
    RippleResult simulate_motor_ripple(const DcMotor                          &motor,
                                       const std::function<MotorLoad(double)> &load,
                                       double cycle_angle, unsigned int n_cycles = 6,
                                       unsigned int steps_per_cycle = 4000);
  } // namespace four_bar
} // namespace compliant
