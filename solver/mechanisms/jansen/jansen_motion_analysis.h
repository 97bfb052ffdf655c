// Velocity and acceleration analysis of the Jansen leg: the loop equations
// (1)-(3) of the seed paper differentiated once and twice in time give two
// linear 6 x 6 systems with the same matrix (the loop Jacobian),
//   J(theta) omega = -r2 omega2 sigma2 (loops 1, 2)                  (paper eqs. 4-6)
//   J(theta) alpha = -r2 alpha2 sigma2 + r2 omega2^2 mu2 + sum r_k omega_k^2 mu_k
//                                                                    (paper eqs. 12-14)
// using d mu/dt = omega sigma, d sigma/dt = -omega mu. The rigid ternary links
// share one rate: omega5' = omega5, omega8' = omega8. Joint velocities and
// accelerations then follow by differentiating each joint's position chain
// (e.g. the foot, paper eqs. 7, 8 and 15: r_H = -r6 mu6 + r8' mu8').
#pragma once

#include <mechanisms/jansen/jansen_joints.h>
#include <mechanisms/jansen/jansen_link_lengths.h>
#include <mechanisms/jansen/jansen_position_analysis.h>

namespace compliant
{
  namespace jansen
  {
    // One rate per moving link other than the crank: angular velocities
    // (rad/s) or angular accelerations (rad/s^2). Link 5 is the ternary CDE,
    // link 8 the ternary FGH.
    struct LinkRates
    {
      double link3 = 0.; // BC
      double link4 = 0.; // BG
      double link5 = 0.; // CDE
      double link6 = 0.; // EG
      double link7 = 0.; // DF
      double link8 = 0.; // FGH
    };

    struct JansenMotion
    {
      LinkRates    angular_velocities;
      LinkRates    angular_accelerations;
      JointVectors velocities;    // length units per second
      JointVectors accelerations; // length units per second squared
    };

    // Velocities and accelerations for crank speed omega2 (rad/s, > 0
    // counter-clockwise) and crank angular acceleration alpha2 (rad/s^2) at
    // the given link angles (normally those of solve_position; any set of
    // angles is accepted, e.g. a paper's rounded ones). Throws
    // std::invalid_argument if the loop Jacobian is singular (dead point) or an
    // input is not finite.
    JansenMotion solve_motion(const JansenLinkLengths &lengths,
                              const LinkAngles        &angles,
                              const double             omega2,
                              const double             alpha2 = 0.);
  } // namespace jansen
} // namespace compliant
