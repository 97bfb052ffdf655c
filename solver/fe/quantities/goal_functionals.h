// Quantities of a linear static run as linear functionals J(v) = j . v of the displacement, the
// right-hand sides of their dual problems (goal-oriented refinement, ladder/goal_refinement.h).
// Point values are regularized: a displacement or a stress "at a point" is its average under a
// smooth bump w(x) = (1 - |x - x0|^2 / r^2)^2 of radius r (Prudhomme and Oden's mollified point
// functionals). An unregularized point functional has a dual of infinite energy (a point force),
// whose indicators would keep refining at the point for ever.
#pragma once

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_vector.h>

#include "elasticity/linear_elastic_problem.h"
#include "quantities/quantities.h"

#include <string>

namespace compliant
{
  // j for quantity `name`, assembled through `homogeneous` (the dual's constraints); false if the
  // quantity is not a linear functional this function knows (the strain energy is energy-like:
  // its dual is the solution itself, see ladder/adaptive_refinement.h). Known:
  // displacement_<point>_<axis>, stress_<point>_<component>[_raw], von_mises_<point>[_raw]
  // (linearized about `values`), mean_displacement_<boundary>_<axis>, rotation_<boundary>_<axis>
  // (Quantities/Rotations), and the reactions of
  // quantities/reaction_weights.h. For a reaction q(v) = a(v, psi) the dual z solves
  // a(v, z) = a(v, psi) and z - psi (minus the harmonic extension of psi) carries the dual's
  // error: `lifting` gets psi then, and stays empty otherwise. radius: of the bump; 0 for half the
  // diameter of the coarse (level 0) cell around the point, the same on every rung.
  template <int dim>
  bool assemble_goal_functional(const LinearElasticProblem<dim> &problem, const std::string &name,
                                const Quantities &values, const dealii::AffineConstraints<double> &homogeneous,
                                dealii::PETScWrappers::MPI::Vector &j, dealii::PETScWrappers::MPI::Vector &lifting,
                                double radius = 0);
} // namespace compliant
