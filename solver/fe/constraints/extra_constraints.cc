#include "constraints/extra_constraints.h"

#include "constraints/edge_supports.h"
#include "constraints/mirror_ties.h"
#include "constraints/pin_joints.h"
#include "input/spec_list.h"

namespace compliant
{
  void declare_extra_constraints(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Extra constraints");
    prm.declare_entry("Edge supports", "", dealii::Patterns::Anything(),
                      "Components held at zero on the DoFs shared by several boundaries (edges in "
                      "3D, corners in 2D): 'bottom & sides: z'. Read by the linear static, linear "
                      "buckling, modal, linkage and nonlinear static analyses (not by buckling about "
                      "a finite-strain state).");
    prm.declare_entry("Mirror ties", "", dealii::Patterns::Anything(),
                      "Ties each node of a boundary to its mirror image across a plane: "
                      "'x_ends: plane=z 0, even=y, odd=z; ...' makes u_y even and u_z odd in z on "
                      "x_ends (u_y(x,y,-z) = u_y(x,y,z), u_z(x,y,-z) = -u_z(x,y,z), so u_z = 0 on "
                      "the plane); unnamed components stay free. The plane is an axis and a "
                      "coordinate (a number or an expression of the geometry parameters); every "
                      "node must have a mirror node on the same boundary. Holds the part of the "
                      "field of one parity and leaves the other free, e.g. the bending part of a "
                      "plate's side faces but not the membrane part (the 3D hard simple support, "
                      "see cases/verification/nafems_fv52.md). Read by the linear static, linear "
                      "buckling, modal, linkage and nonlinear static analyses (exact at finite "
                      "strain; not read by buckling about a finite-strain state).");
    prm.declare_entry("Pins", "", dealii::Patterns::Anything(),
                      "Frictionless pin joints: 'B: pin_B, eye_AB_B, eye_BC_B; ...', the pin "
                      "disk's boundary first, then the eyes (holes of the same radius, meshed with "
                      "the same nodes on the circle). Radial displacements are tied, tangential "
                      "sliding is free: force, no moment (in 3D each node of an eye is held radially, "
                      "one also axially: a revolute joint). Clamp a pin's boundary to pin it to the "
                      "ground. 'joint=bonded' in an item welds that joint instead. Read by the "
                      "linear static, linear buckling, modal, linkage and nonlinear static analyses; "
                      "at finite strain the radial ties keep their reference directions (joints "
                      "that turn little: a link turned by theta on its pin is off by about r "
                      "theta^2 / 2).");
    prm.leave_subsection();
  }

  ExtraConstraints read_extra_constraints(const dealii::ParameterHandler &prm)
  {
    return {trim(prm.get({"Extra constraints"}, "Edge supports")),
            trim(prm.get({"Extra constraints"}, "Mirror ties")),
            trim(prm.get({"Extra constraints"}, "Pins"))};
  }

  template <int dim>
  void add_extra_constraints(const Discretization<dim> &problem,
                             const ExtraConstraints          &extra,
                             dealii::AffineConstraints<double> &constraints)
  {
    add_edge_supports(problem, extra.edge_supports, "Extra constraints/Edge supports", constraints);
    add_mirror_ties(problem, extra.mirror_ties, "Extra constraints/Mirror ties", constraints);
    add_pin_joints(problem, extra.pins, "Extra constraints/Pins", constraints);
  }

  template void add_extra_constraints<2>(const Discretization<2> &, const ExtraConstraints &,
                                         dealii::AffineConstraints<double> &);
  template void add_extra_constraints<3>(const Discretization<3> &, const ExtraConstraints &,
                                         dealii::AffineConstraints<double> &);
} // namespace compliant
