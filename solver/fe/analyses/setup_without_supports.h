// Set-up of a structure that may have no supports at all (free-free modal analysis):
// LinearElasticProblem<dim>::setup() rejects such a case because a static solve would be
// singular, so this stops after setup_discretization().
#pragma once

#include "elasticity/linear_elastic_problem.h"

namespace compliant
{
  // Throws std::invalid_argument naming the entry for bad case-file names, like setup().
  template <int dim>
  void setup_without_supports(LinearElasticProblem<dim> &problem);

  // True if the case names any Dirichlet condition (Clamped, Displacement or Rotation).
  bool has_supports(const CaseParameters &parameters);
} // namespace compliant
