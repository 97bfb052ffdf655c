// Exact large deflection of an inextensible, shear-rigid (Euler elastica) cantilever of length L,
// clamped at s = 0 along the x axis. Results are normalised: rotation in rad, deflection and
// shortening divided by L.
#ifndef CLOSED_FORMS_ELASTICA_H
#define CLOSED_FORMS_ELASTICA_H

namespace closed_forms
{
  struct CantileverTip
  {
    double rotation;    // tip slope angle (rad), same sign as the load
    double deflection;  // transverse tip displacement v / L
    double shortening;  // axial tip displacement towards the clamp -u / L (>= 0)
  };

  // End moment M: constant curvature, the beam rolls up into a circular arc.
  // t = M L / (E I); v/L = (1 - cos t)/t, shortening = 1 - sin t / t.
  CantileverTip end_moment_elastica(double t);

  // Dead transverse tip load P (keeps its direction), alpha = P L^2 / (E I) (Bisshopp and Drucker,
  // Q. Appl. Math. 3:272, 1945), evaluated with Carlson's elliptic integrals. |alpha| <= 1e5.
  CantileverTip tip_load_elastica(double alpha);

  // Incomplete elliptic integrals of the first and second kind with parameter m = k^2 (DLMF 19.2.4-5),
  // 0 <= phi <= pi/2, m <= 1. Exposed for tests.
  double elliptic_f(double phi, double m);
  double elliptic_e(double phi, double m);
} // namespace closed_forms

#endif
