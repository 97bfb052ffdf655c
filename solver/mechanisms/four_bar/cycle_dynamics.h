// Crank torque, motor torque and power over one motion cycle of the rigid and of the compliant
// (PRBM) flap mechanism at constant motor speed: inverse dynamics of the one-degree-of-freedom
// Lagrangian model (see generalized_inertia.h), springs by Eq. 12.
#pragma once

#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/generalized_inertia.h>
#include <mechanisms/four_bar/motion_law.h>
#include <mechanisms/four_bar/position_analysis.h>
#include <mechanisms/four_bar/prbm_springs.h>

#include <array>
#include <vector>

namespace compliant
{
  namespace four_bar
  {
    struct FlapMechanism
    {
      LinkLengths           lengths;
      MovingLinkMasses      masses;
      PrbmSprings           springs;
      std::array<double, 2> gravity; // [m/s^2] in the ground frame (x along AD)
      AssemblyBranch        branch;  // branch at the start of the motion
    };

    struct CycleSample
    {
      double                 time;
      double                 motor_angle;
      CrankState             crank;
      Pose                   pose;
      DerivativeCoefficients coefficients;
      double                 transmission_angle;
      // Crank torques [N m]: J a2 + 1/2 J' w2^2, dV_g/dth2 and dU/dth2 (Eq. 12).
      double inertia_torque;
      double gravity_torque;
      double spring_torque;
      // Energies [J]: kinetic, gravity potential, springs.
      double kinetic_energy;
      double gravity_energy;
      double spring_energy;

      double rigid_crank_torque() const { return inertia_torque + gravity_torque; }
      double compliant_crank_torque() const { return rigid_crank_torque() + spring_torque; }
    };

    // n_samples poses at motor angles phi_j = (j + 1/2) cycle / n_samples, j = 0..n-1, where
    // cycle = 2 pi n_motor_turns (the half-step offset keeps samples off the singular fold of a
    // change-point linkage in full rotation). Throws std::invalid_argument for bad input and
    // std::domain_error if a sample lands on a dead point.
    std::vector<CycleSample> evaluate_cycle(const FlapMechanism &mechanism, const MotionLaw &motion,
                                            double motor_speed, unsigned int n_samples,
                                            unsigned int n_motor_turns = 1);

    // Statistics of one torque signal over a cycle of equally spaced samples.
    struct TorqueStatistics
    {
      double peak;       // max |T|
      double rms;        // sqrt(mean T^2)
      double range;      // max T - min T
      double peak_power; // max |T w| [W]
      double rms_power;  // sqrt(mean (T w)^2) [W]
    };

    enum class TorqueComponent
    {
      inertia,  // rigid mechanism without gravity
      rigid,    // inertia + gravity
      springs,  // PRBM springs alone (quasi-static)
      compliant // inertia + gravity + springs
    };

    enum class TorqueReference
    {
      crank, // torque on link AB
      motor  // torque at the motor shaft of the ideal driver: crank torque * dth2/dphi
    };

    TorqueStatistics torque_statistics(const std::vector<CycleSample> &samples,
                                       TorqueComponent component, TorqueReference reference);

    // Everything the motor sees at motor angle phi: reduced inertia J_phi = J s^2, its
    // derivative dJ_phi/dphi = J' s^3 + 2 J s s', and the generalized force
    // Q_phi = (dV_g/dth2 + dU/dth2) s, with the branch held fixed (for windows free of dead
    // points). include_springs = false gives the rigid mechanism.
    struct ReflectedLoad
    {
      double inertia;
      double inertia_derivative;
      double generalized_force;
    };

    ReflectedLoad reflected_load(const FlapMechanism &mechanism, const MotionLaw &motion,
                                 double motor_angle, bool include_springs);
  } // namespace four_bar
} // namespace compliant
