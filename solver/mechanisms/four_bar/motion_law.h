// How the crank th2 follows the motor angle phi = w t at constant motor speed w.
//
// The flap paper drives the crank at a constant 60 rpm in its model (sec. 3) but also says the
// flap sweeps 26 deg, and in its fatigue rig a 60 rpm motor turns a separate rigid four-bar whose
// 26 deg rocker rocks the compliant part (sec. 2.2). A one-piece compliant crank cannot turn
// through 360 deg (its flexure at A would wind up), so the compliant mechanism must oscillate.
// The rig's dimensions are not given: it is idealised here as a massless harmonic driver
// (Scotch yoke), th2 = th2_start + (sweep/2)(1 - cos phi), one out-and-back sweep per motor
// revolution. The full rotation is kept for the rigid linkage, as the paper's model literally
// states.
#pragma once

namespace compliant
{
  namespace four_bar
  {
    enum class MotionKind
    {
      harmonic_oscillation,
      full_rotation
    };

    struct CrankState
    {
      double angle;                  // th2
      double velocity;               // dth2/dt
      double acceleration;           // d2th2/dt2
      double drive_ratio;            // s  = dth2/dphi: motor torque = crank torque * s
      double drive_ratio_derivative; // s' = d2th2/dphi2
    };

    struct MotionLaw
    {
      MotionKind kind;
      double     start_angle; // th2 at phi = 0 [rad]
      double     sweep;       // peak-to-peak crank oscillation [rad] (harmonic_oscillation only)

      // Throws std::invalid_argument if the start angle is not finite or, for an oscillation,
      // the sweep is not positive and finite.
      void check() const;

      CrankState at(double motor_angle, double motor_speed) const;
    };
  } // namespace four_bar
} // namespace compliant
