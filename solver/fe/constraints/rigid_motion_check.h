// Whether the constraints of a static problem hold every rigid-body motion of the part. A support
// that leaves a translation or a rotation free (a mechanism: 'Displacement = left: x=0' alone)
// makes the stiffness matrix singular; a direct solver then returns displacements of 1e11
// without complaint, and an iterative one fails after its last iteration. This check finds the
// free motions before any solve and names them.
//
// It tests the rigid motions of each body of the mesh (cells joined through shared vertices: a
// volume gmsh did not glue to its neighbour is a body of its own) against every constraint line
// of a locally owned DoF (supports, edge supports, mirror ties, pins, rigid boundaries, hanging
// nodes). On a distributed mesh, and beyond 100 bodies, the whole mesh is tested as one body.
// Contact, which may hold the part once it touches, is the caller's to exclude.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>

#include "constraints/rigid_boundary.h"

#include <string>
#include <vector>

namespace compliant
{
  struct FreeRigidMotions
  {
    // False when some line names a DoF this rank cannot place (a tie to a far node): the check
    // then says nothing rather than risk a false alarm.
    bool                     decided = true;
    unsigned int             count    = 0; // free motions: the dimension of their space
    unsigned int             n_bodies = 1; // separate bodies of the mesh
    std::vector<std::string> motions; // 'translation along y', 'rotation about x through (0, 2.5, 0)'

    bool any() const { return decided && count > 0; }
    // 'translation along y, translation along z and rotation about x through (...)'
    std::string describe() const;
  };

  // The displacement components are the first dim of the element's (a mixed element's pressure is
  // not looked at). The bodies the `joining_boundaries` (rigid boundaries' ids) touch are one
  // rigid piece; a line of a DoF in `follow_rigid_motions` (a rigid boundary's) that names a
  // master this rank cannot place is left out, which is exact for the rigid boundary's own lines.
  // Collective over the DoF handler's communicator.
  template <int dim>
  FreeRigidMotions free_rigid_motions(const dealii::Mapping<dim>              &mapping,
                                      const dealii::DoFHandler<dim>           &dof_handler,
                                      const dealii::AffineConstraints<double> &constraints,
                                      const dealii::IndexSet                  &follow_rigid_motions,
                                      const std::vector<int>                  &joining_boundaries);

  // Throws std::invalid_argument naming the free motions if the constraints leave any ('what':
  // 'a linear static solve'). The rigid boundaries' lines are left out (see above).
  template <int dim>
  void require_rigid_motion_held(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                                 const dealii::AffineConstraints<double> &constraints,
                                 const std::vector<RigidBoundary<dim>>   &rigid_boundaries,
                                 const std::string                       &what);

  // The same for a problem that has them all (LinearElasticProblem, FiniteStrainProblem).
  template <typename Problem>
  void require_rigid_motion_held(const Problem &problem, const dealii::AffineConstraints<double> &constraints,
                                 const std::string &what)
  {
    require_rigid_motion_held(*problem.mapping, problem.dof_handler, constraints, problem.rigid_boundaries, what);
  }
} // namespace compliant
