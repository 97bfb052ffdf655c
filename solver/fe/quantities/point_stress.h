// Stress at named points (Quantities/Stress points): every Cauchy stress component, von Mises
// and the principal stresses, from the stress field recovered by L2 projection onto continuous
// elements of the displacement's degree (smooth across cells), with the raw value from the
// displacement gradient in the cell that holds the point beside it ("_raw": discontinuous
// across cells, what a quadrature-point readout would give).
#pragma once

#include "quantities/quantities.h"

namespace compliant
{
  // Points inside the mesh, names and coordinates well formed; throws std::invalid_argument.
  template <class Problem>
  void validate_point_stresses(const Problem &problem);

  // Adds, for each point <p>: stress_<p>_<xx|yy|zz|xy[|xz|yz]>, von_mises_<p>,
  // principal_stress_<p>_<1|2|3> (largest first; sigma_zz of 2D models included) and the same
  // components and von Mises with the suffix _raw.
  template <class Problem>
  void add_point_stresses(const Problem &problem, Quantities &q);
} // namespace compliant
