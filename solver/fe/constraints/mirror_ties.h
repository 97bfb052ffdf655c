// Mirror ties: on a boundary, the displacement at each node is tied to the one at the node's mirror
// image across a plane, component by component, even (u(p') = u(p)) or odd (u(p') = -u(p), hence
// zero on the plane). Holding the part of the field of one parity and leaving the other free is a
// support that no face condition can express. NAFEMS FV52 uses it for the 3D counterpart of the
// plate-theory hard simple support: on the side faces the bending part of the field (deflection
// even in z, tangential displacement odd in z) is held, the membrane part is free; see
// cases/verification/nafems_fv52.md.
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include "discretization/discretization.h"

#include <string>

namespace compliant
{
  // spec: 'x_ends: plane=z 0, even=y, odd=z; ...': boundary name, mirror plane (axis and
  // coordinate, an expression of the geometry parameters), the components whose field is made
  // even and odd in the mirror coordinate (space-separated lists). The node on the side of larger
  // coordinate becomes dependent on its mirror. A tie already implied is skipped; a DoF already
  // constrained otherwise gets its mirror tied to it. constraints: every rank's lines, not closed
  // (gather_constraints). Throws std::invalid_argument naming `where`: unknown boundary or
  // component, a node without a mirror node on the same boundary, or a tie that contradicts a
  // constraint already there.
  template <int dim>
  void add_mirror_ties(const Discretization<dim> &problem, const std::string &spec,
                       const std::string &where, dealii::AffineConstraints<double> &constraints);
} // namespace compliant
