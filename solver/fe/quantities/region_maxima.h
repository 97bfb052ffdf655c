// Peak strain and stress per body (Quantities/Region maxima): for each named physical body, the
// largest principal strain and the largest von Mises stress over its cells, with where they occur,
// so that the hot spot of each flexure of a mechanism can be followed step by step.
#pragma once

#include "quantities/quantities.h"

namespace compliant
{
  // Checks the names of Quantities/Region maxima against the mesh's bodies before any solve.
  // Throws std::invalid_argument naming the entry and listing the bodies.
  template <class Problem>
  void validate_region_maxima(const Problem &problem);

  // Adds max_principal_strain_in_<body>, max_von_mises_in_<body> and the reference coordinates
  // of each maximum (..._x, _y[, _z]). The strain is the largest eigenvalue of the small strain
  // (linear problems) or the engineering principal stretch lambda_1 - 1 (finite strain), of
  // the in-plane deformation in 2D. Sampled at quadrature points and element nodes.
  template <class Problem>
  void add_region_maxima(const Problem &problem, Quantities &q);
} // namespace compliant
