// Switching forces of a bistable pre-curved (cosine) clamped-clamped beam whose second (antisymmetric)
// mode is held, as in the double beam with a tied centre of Qiu, Lang and Slocum (J. MEMS 13:137,
// 2004): the force at the centre that snaps it forward, and the one that pulls it back.
#ifndef CLOSED_FORMS_BISTABLE_H
#define CLOSED_FORMS_BISTABLE_H

namespace closed_forms
{
  // Per beam: span L, apex height h of the centre line, in-plane thickness t, out-of-plane width b.
  // F_top ~ 740 E I h / L^3 and F_bottom ~ 370 E I h / L^3, I = b t^3 / 12: the limits for a shallow
  // beam (h << L) of large Q = h / t; bistable only for Q > 2.31.
  double bistable_switching_force_top(double L, double E, double b, double t, double h);
  double bistable_switching_force_bottom(double L, double E, double b, double t, double h);
  constexpr double bistable_minimum_q = 2.31;
} // namespace closed_forms

#endif
