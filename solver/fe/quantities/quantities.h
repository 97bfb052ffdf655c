// Quantities of interest of a solved linear elastic problem, as a flat name -> value table:
// reactions and moments on supported boundaries, stiffness of driven boundaries, point and mean
// displacements, best-fit boundary rotations, peak von Mises stress, strain energy.
#pragma once


#include <map>
#include <string>

namespace compliant
{
  using Quantities = std::map<std::string, double>;

  // Checks the Quantities entries (names, points inside the mesh) before the solve, so a bad
  // request costs no solve and leaves no output. Throws std::invalid_argument.
  // Problem: LinearElasticProblem<dim> or FiniteStrainProblem<dim>.
  template <class Problem>
  void validate_quantity_requests(const Problem &problem);

  template <class Problem>
  Quantities compute_quantities(const Problem &problem);
} // namespace compliant
