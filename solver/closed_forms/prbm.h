// Pseudo-rigid-body models (Howell, Compliant Mechanisms, Wiley 2001, ch. 5) for a flexure of
// length l with a rectangular section (width b, depth h in the bending direction, I = b h^3 / 12).
#ifndef CLOSED_FORMS_PRBM_H
#define CLOSED_FORMS_PRBM_H

#include <cmath>

namespace closed_forms
{
  // Howell's cantilever-with-end-force parameters (pure transverse load: gamma = 0.8517).
  constexpr double prbm_characteristic_radius_factor = 0.85;  // gamma
  constexpr double prbm_stiffness_coefficient = 2.65;         // K_Theta
  // Pseudo-rigid-body angle up to which the parametric approximation holds (Howell 2001, 64 deg).
  constexpr double prbm_max_angle = 64.0 * M_PI / 180.0;

  // Small-length flexural pivot: torsional spring K = E I / l at the flexure centre.
  double prbm_pivot_stiffness(double E, double b, double h, double l);

  // Cantilever with end force: torsional spring K = gamma K_Theta E I / l at distance gamma l from
  // the free end.
  double prbm_cantilever_force_stiffness(double E, double b, double h, double l,
                                         double gamma = prbm_characteristic_radius_factor,
                                         double K_theta = prbm_stiffness_coefficient);

  struct PlanarPoint
  {
    double x;  // along the undeflected flexure, measured from the clamp
    double y;  // transverse
  };

  // Tip position for the pseudo-rigid-body angle Theta (rad):
  // x = l (1 - gamma (1 - cos Theta)), y = gamma l sin Theta.
  PlanarPoint prbm_cantilever_tip_position(double l, double Theta,
                                           double gamma = prbm_characteristic_radius_factor);

  // Dead transverse tip force that holds the PRBM cantilever at Theta: the spring torque
  // K Theta balances P times the moment arm gamma l cos Theta.
  double prbm_cantilever_tip_force(double E, double b, double h, double l, double Theta,
                                   double gamma = prbm_characteristic_radius_factor,
                                   double K_theta = prbm_stiffness_coefficient);
} // namespace closed_forms

#endif
