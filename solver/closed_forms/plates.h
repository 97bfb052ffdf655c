// Buckling of flat rectangular plates (plain C++).
#ifndef CLOSED_FORMS_PLATES_H
#define CLOSED_FORMS_PLATES_H

namespace closed_forms
{
  // Uniform compressive stress (along a) that buckles a rectangular plate, simply supported on all
  // four edges, into m half-waves along the load (length a) and n across it (width b), thickness t:
  // Kirchhoff, sigma = (pi^2 D / (b^2 t)) (m b / a + n^2 a / (m b))^2, D = E t^3 / (12 (1 - nu^2))
  // (Timoshenko and Gere, Theory of Elastic Stability, sec. 9.2); a square plate in one half-wave
  // each way gives the classical k = 4.
  double plate_buckling_stress(double a, double b, double t, double E, double nu, double m, double n);

  // The share by which transverse shear lowers it (Mindlin's simply supported plate, shear factor
  // kappa): sigma_Mindlin = sigma_Kirchhoff / (1 + c), c = pi^2 D ((m/a)^2 + (n/b)^2) / (kappa G t).
  // Returns c; about 2 (pi t / b)^2 / (6 kappa (1 - nu)) for a square plate in its first mode.
  double plate_buckling_shear_share(double a, double b, double t, double E, double nu, double m, double n,
                                    double kappa = 5.0 / 6.0);
} // namespace closed_forms

#endif
