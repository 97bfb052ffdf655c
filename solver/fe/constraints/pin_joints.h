// Frictionless pin joints between separate bodies (links of a linkage). A pin is a small disk
// body; each link has an eye (hole) of the same radius around it, meshed with the same nodes
// along the circle. At every node the eye's radial displacement equals the pin's, the tangential
// one is free: the contact forces are radial, so the joint carries force but no moment (a
// linear, bilateral contact: the eye may also pull on the pin). One node of the first eye is tied
// fully to the pin to take out the pin's free spin; by the pin's moment equilibrium that tie
// carries no tangential force. A pin whose boundary is clamped is a pin in the ground. In 3D the
// radial ties act at every height (the eye cannot tilt on the pin: a revolute joint) and one node
// of each eye is held along the pin's axis.
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include "discretization/discretization.h"

#include <string>

namespace compliant
{
  // spec: 'B: pin_B, eye_AB_B, eye_BC_B; E: pin_E, eye_CDE_E, eye_EG_E': the pin's boundary
  // first, then the eyes; 'joint=bonded' in an item ties every node fully instead (a welded
  // joint, to compare with models that glue their links). constraints: every rank's lines, not closed (gather_constraints).
  // Throws std::invalid_argument naming `where`: unknown boundary, nodes that do not match, an
  // eye that is supported or in another pin.
  template <int dim>
  void add_pin_joints(const Discretization<dim> &problem, const std::string &spec,
                      const std::string &where, dealii::AffineConstraints<double> &constraints);
} // namespace compliant
