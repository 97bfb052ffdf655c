// Motor speed ripple against the closed-form response of a first-order system.
#include <mechanisms/four_bar/motor_ripple.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace compliant::four_bar;

TEST(MotorRipple, SinusoidalLoadGivesFirstOrderResponse)
{
  // Constant inertia J_t = J_m + J, load Q = T0 sin(phi). Linearised about W_0 (ripple << W_0):
  // J_t dW/dt = -c (W - W_0) - T0 sin(W_0 t), c = T_stall / W_0, whose steady ripple
  // (peak to peak) is 2 T0 / sqrt(c^2 + (J_t W_0)^2).
  const DcMotor motor{2. * M_PI, 1.0, 2e-2};
  const double  J = 3e-3, T0 = 1e-3;
  const auto    load = [&](const double phi) {
    return MotorLoad{J, 0., T0 * std::sin(phi)};
  };
  const RippleResult r = simulate_motor_ripple(motor, load, 2. * M_PI, 10, 4000);
  const double       c = motor.stall_torque / motor.no_load_speed, Jt = motor.reflected_inertia + J;
  const double       expected = 2. * T0 / std::hypot(c, Jt * motor.no_load_speed);
  // Linearisation error ~ ripple / W_0 ~ 1e-3.
  EXPECT_NEAR(r.ripple, expected, 5e-3 * expected);
  EXPECT_NEAR(r.mean_speed, motor.no_load_speed, 1e-5 * motor.no_load_speed);
  EXPECT_NEAR(r.quasi_static_ripple, motor.no_load_speed * 2. * T0 / motor.stall_torque, 1e-9);
}

TEST(MotorRipple, SmallInertiaApproachesTheQuasiStaticEstimate)
{
  const DcMotor motor{2. * M_PI, 1.0, 1e-4};
  const auto    load = [](const double phi) {
    return MotorLoad{0., 0., 1e-3 * std::cos(phi)};
  };
  const RippleResult r = simulate_motor_ripple(motor, load, 2. * M_PI);
  // Attenuation 1/sqrt(1 + (J_m W_0^2 / T_stall)^2) - 1 = 8e-6; RK4 error far below.
  EXPECT_NEAR(r.ripple, r.quasi_static_ripple, 1e-4 * r.quasi_static_ripple);
}

TEST(MotorRipple, StallAndBadMotorThrow)
{
  const DcMotor motor{2. * M_PI, 1.0, 1e-3};
  const auto    heavy = [](const double) {
    return MotorLoad{0., 0., 5.};
  };
  EXPECT_THROW(simulate_motor_ripple(motor, heavy, 2. * M_PI), std::domain_error);
  const auto light = [](const double) {
    return MotorLoad{0., 0., 0.};
  };
  EXPECT_THROW(simulate_motor_ripple({2. * M_PI, 0., 1e-3}, light, 2. * M_PI),
               std::invalid_argument);
}
