// A reaction quantity as a linear functional of the residual r = f_int(u) - f at its boundary's
// DoFs, q = sum_i psi_i r_i: the dual of a reaction is then the harmonic extension of psi
// (goal-oriented refinement, quantities/goal_functionals.h). Defined beside the reactions it
// mirrors, in quantities.cc.
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "elasticity/linear_elastic_problem.h"

#include <string>

namespace compliant
{
  // psi (locally owned DoFs) for reaction_force_<b>_<axis>, reaction_moment_<b>_<axis>,
  // rotational_stiffness_<b> and stiffness_<b>_<axis>; false for any other name.
  template <int dim>
  bool reaction_weights(const LinearElasticProblem<dim> &problem, const std::string &name,
                        dealii::PETScWrappers::MPI::Vector &psi);
} // namespace compliant
