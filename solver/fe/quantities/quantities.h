// Quantities of interest of a solved linear elastic problem, as a flat name -> value table:
// reactions and moments on supported boundaries, stiffness of driven boundaries, point and mean
// displacements, best-fit boundary rotations, peak von Mises stress, strain energy.
#pragma once

#include "elasticity/linear_elastic_problem.h"

#include <map>
#include <string>

namespace compliant
{
  using Quantities = std::map<std::string, double>;

  // Checks the Quantities entries (names, points inside the mesh) before the solve, so a bad
  // request costs no solve and leaves no output. Throws std::invalid_argument.
  template <int dim>
  void validate_quantity_requests(const LinearElasticProblem<dim> &problem);

  template <int dim>
  Quantities compute_quantities(const LinearElasticProblem<dim> &problem);
} // namespace compliant
