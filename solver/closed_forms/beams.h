// Linear beam formulas for a rectangular section: width b (out of the bending plane), depth h (in the
// bending direction), I = b h^3 / 12, A = b h; isotropic material E, nu, G = E / (2 (1 + nu)).
// Any consistent unit system works (e.g. N, mm, MPa, t/mm^3).
#ifndef CLOSED_FORMS_BEAMS_H
#define CLOSED_FORMS_BEAMS_H

namespace closed_forms
{
  // Shear correction factor of a rectangle used throughout (Timoshenko; Cowper's 10(1+nu)/(12+11nu)
  // is the alternative, 0.85 at nu = 0.3).
  constexpr double rectangle_shear_coefficient = 5.0 / 6.0;

  double second_moment_of_area(double b, double h);
  double section_area(double b, double h);
  double shear_modulus(double E, double nu);

  // Tip deflection of a cantilever under a transverse tip load P: P L^3 / (3 E I).
  double euler_bernoulli_cantilever_deflection(double P, double L, double E, double b, double h);

  // Adds the shear deflection P L / (kappa G A) (Timoshenko beam).
  double timoshenko_cantilever_deflection(double P, double L, double E, double nu, double b, double h,
                                          double kappa = rectangle_shear_coefficient);

  // Exact plane-stress elasticity solution of a cantilever with a parabolic end shear P whose
  // clamped end follows the same solution (Timoshenko and Goodier, Theory of Elasticity, sec. 21;
  // Augarde and Deeks, Finite Elem. Anal. Des. 44, 2008): deflection of the centroid of the loaded
  // end, P L^3/(3 E I) + (4 + 5 nu) P h^2 L/(24 E I).
  double timoshenko_goodier_cantilever_deflection(double P, double L, double E, double nu, double b,
                                                  double h);

  // Fixed-guided beam (both ends clamped, one end free to translate transversely): 12 E I / L^3.
  double euler_bernoulli_guided_stiffness(double L, double E, double b, double h);

  // 12 E I / (L^3 (1 + Phi)), Phi = 12 E I / (kappa G A L^2).
  double timoshenko_guided_stiffness(double L, double E, double nu, double b, double h,
                                     double kappa = rectangle_shear_coefficient);

  // Buckling load of a prismatic column, pi^2 E I / (K L)^2 (Euler), K the effective-length factor
  // of its ends: 2 fixed-free, 1 pinned-pinned, 0.6992 fixed-pinned, 0.5 fixed-fixed; h is the depth
  // in the buckling direction.
  double euler_column_load(double L, double E, double b, double h, double K);

  // The same with Engesser's shear correction, P_E / (1 + P_E / (kappa G A)) (Timoshenko and Gere,
  // Theory of Elastic Stability, sec. 2.18).
  double engesser_column_load(double L, double E, double nu, double b, double h, double K,
                              double kappa = rectangle_shear_coefficient);

  // End-moment stiffness M / theta of a cantilever (fixed-free beam-column) under an axial end force
  // P that keeps its direction, P > 0 compressive: (E I / L) kL / tan kL, k = sqrt(P / (E I)); in
  // tension (P < 0) (E I / L) kL / tanh kL; E I / L without axial force. Zero at the buckling load
  // (kL = pi/2), negative beyond it (Timoshenko and Gere, Theory of Elastic Stability, sec. 1.5).
  double beam_column_end_moment_stiffness(double L, double E, double b, double h, double P);

  // Transverse stiffness F / delta of a fixed-guided beam (one end clamped, the other translating
  // sideways without turning: a blade of a parallel-guided flexure) under an axial force P that keeps
  // its direction, P > 0 compressive, q = L sqrt(|P| / E I): the exact beam-column result,
  // (E I / L^3) q^3 sin q / (2 (1 - cos q) - q sin q) in compression, with sinh and cosh
  // (q^3 sinh q / (q sinh q - 2 (cosh q - 1))) in tension; 12 E I / L^3 without axial force, zero at
  // the sway buckling load P = pi^2 E I / L^2, negative beyond it.
  double guided_beam_column_stiffness(double L, double E, double b, double h, double P);

  // The same by the beam constraint model (Awtar, Slocum and Sevincer, J. Mech. Des. 129:625, 2007):
  // its series to second order in the normalized tension p = -P L^2 / E I, (E I / L^3)(12 + 6/5 p -
  // p^2 / 700), which keeps the load-stiffening of a blade in closed form (third-order error in p).
  double bcm_guided_stiffness(double L, double E, double b, double h, double P);

  // Lateral-torsional buckling moment of a narrow rectangular strip (depth h in the bending plane,
  // width b < h), simply supported with fork ends (twist and lateral deflection held, warping and
  // both end rotations free) under a uniform moment: M_cr = (pi / L) sqrt(E I_y G J), I_y = h b^3 / 12,
  // J = beta h b^3 (Timoshenko and Gere, Theory of Elastic Stability, sec. 6.2). Linear: the
  // in-plane curvature before buckling, which raises it by 1/sqrt((1 - I_y/I_z)(1 - G J/E I_z)),
  // is left out.
  double lateral_torsional_buckling_moment(double L, double E, double nu, double h, double b);

  // n-th positive root x = beta_n L of 1 + cos x cosh x = 0 (clamped-free beam), n >= 1.
  double cantilever_frequency_root(unsigned int n);

  // omega_n = (beta_n L)^2 sqrt(E I / (rho A L^4)) in rad per unit time.
  double euler_bernoulli_cantilever_angular_frequency(unsigned int n, double L, double E, double rho,
                                                      double b, double h);

  // omega_n / (2 pi), cycles per unit time (Hz with SI or N-mm-t units).
  double euler_bernoulli_cantilever_frequency(unsigned int n, double L, double E, double rho,
                                              double b, double h);
} // namespace closed_forms

#endif
