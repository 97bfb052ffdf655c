// Torsion of a solid rectangular bar with sides a >= b (either order is accepted; the sides are
// sorted). Saint-Venant (free warping): Timoshenko and Goodier, Theory of Elasticity, 3rd ed., sec. 109.
// Restrained warping: Vlasov's non-uniform torsion with the warping constant of the Saint-Venant
// warping function.
#ifndef CLOSED_FORMS_TORSION_H
#define CLOSED_FORMS_TORSION_H

namespace closed_forms
{
  // J = beta a b^3, beta = (1/3)[1 - (192/pi^5)(b/a) sum_{n odd} tanh(n pi a/(2b)) / n^5].
  double saint_venant_beta(double a, double b);

  // Stress factor k = 1 - (8/pi^2) sum_{n odd} 1 / (n^2 cosh(n pi a/(2b))): tau_max = k G theta' b.
  double saint_venant_stress_factor(double a, double b);

  // alpha = beta / k so that tau_max = T / (alpha a b^2), at the middle of the long side.
  double saint_venant_alpha(double a, double b);

  // J = beta a b^3.
  double torsion_constant(double a, double b);

  // tau_max = T / (alpha a b^2).
  double saint_venant_max_shear_stress(double T, double a, double b);

  // G J / L (free warping at both ends).
  double saint_venant_torsion_stiffness(double a, double b, double L, double E, double nu);

  // Saint-Venant warping function omega(x, y) per unit twist rate (axial displacement w = theta' omega)
  // about the centroid, for x along side a and y along side b, |x| <= a/2, |y| <= b/2; right-handed
  // twist (u = -theta' z y, v = theta' z x).
  double warping_function(double a, double b, double x, double y);

  // Gamma = integral of omega^2 over the section (omega has zero mean and the centroid is the shear
  // centre, so no shift is needed).
  double warping_constant(double a, double b);

  // Bar clamped at both ends with warping restrained (Vlasov):
  // k = G J / [L - (2/lambda) tanh(lambda L / 2)], lambda = sqrt(G J / (E Gamma)).
  double vlasov_torsion_stiffness(double a, double b, double L, double E, double nu);
} // namespace closed_forms

#endif
