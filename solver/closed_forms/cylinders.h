// Thick-walled cylinder (Lame): inner radius a, outer radius b, pressures p_i inside and p_o
// outside (positive pushing on the wall), linear isotropic material. Timoshenko and Goodier,
// Theory of Elasticity, 3rd ed., sec. 28. With A = (p_i a^2 - p_o b^2)/(b^2 - a^2) and
// B = (p_i - p_o) a^2 b^2/(b^2 - a^2): sigma_r = A - B/r^2, sigma_theta = A + B/r^2.
#ifndef CLOSED_FORMS_CYLINDERS_H
#define CLOSED_FORMS_CYLINDERS_H

namespace closed_forms
{
  // Radial displacement at radius r (a <= r <= b). Plane strain (a long cylinder, eps_z = 0):
  // u = (1+nu)/E [(1-2nu) A r + B/r]; plane stress (a thin ring, sigma_z = 0):
  // u = [(1-nu) A r + (1+nu) B/r]/E.
  double lame_radial_displacement(double a, double b, double p_i, double p_o, double E, double nu,
                                  double r, bool plane_strain);

  // sigma_r and sigma_theta at radius r.
  double lame_radial_stress(double a, double b, double p_i, double p_o, double r);
  double lame_hoop_stress(double a, double b, double p_i, double p_o, double r);
} // namespace closed_forms

#endif
