// Reactions and boundary rotations as linear functionals of DoF values, for their duals.
// A reaction quantity as a linear functional of the residual r = f_int(u) - f at its boundary's
// DoFs, q = sum_i psi_i r_i: the dual of a reaction is then the harmonic extension of psi
// (goal-oriented refinement, quantities/goal_functionals.h). Defined beside the reactions it
// mirrors, in quantities.cc.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/petsc_vector.h>

#include "elasticity/linear_elastic_problem.h"

#include <array>
#include <string>

namespace compliant
{
  // psi (locally owned DoFs) for reaction_force_<b>_<axis>, reaction_moment_<b>_<axis>,
  // rotational_stiffness_<b> and stiffness_<b>_<axis>; false for any other name.
  template <int dim>
  bool reaction_weights(const LinearElasticProblem<dim> &problem, const std::string &name,
                        dealii::PETScWrappers::MPI::Vector &psi);

  // The rigid motion t + w x x at x as its value in component c: R_c(x) . (t, w).
  template <int dim>
  std::array<double, 6> rigid_motion_row(const dealii::Point<dim> &x, const unsigned int c)
  {
    std::array<double, 6> row{};
    row[c] = 1;
    dealii::Tensor<1, 3> position;
    for (unsigned int d = 0; d < dim; ++d)
      position[d] = x[d];
    for (unsigned int j = 0; j < 3; ++j)
      {
        dealii::Tensor<1, 3> e;
        e[j]       = 1;
        row[3 + j] = dealii::cross_product_3d(e, position)[c];
      }
    return row;
  }

  // rotation_<b>_<axis> of Quantities/Rotations is the least-squares rigid fit over boundary b,
  // q(u) = int_b sum_c (g . R_c(x)) u_c dA: g and b's id; false for any other name.
  template <int dim>
  bool rotation_weights(const LinearElasticProblem<dim> &problem, const std::string &name,
                        std::array<double, 6> &g, int &boundary_id);
} // namespace compliant
