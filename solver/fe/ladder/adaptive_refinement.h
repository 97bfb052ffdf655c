// Adaptive refinement for the model ladder: Kelly's gradient-jump indicator on the solved linear
// model marks the cells with the largest indicators, and the marks are returned as refine flags
// that create_triangulation replays (CaseParameters::adaptive_refinements) so that every later
// model, linear or finite strain, is built on the same adapted mesh with hanging-node constraints.
#pragma once

#include "elasticity/linear_elastic_problem.h"

#include <vector>

namespace compliant
{
  // Refine flags (as Triangulation::save_refine_flags writes them, the same on every rank) marking the cells whose Kelly
  // indicators make up the given fraction of cells, largest first; the level difference across
  // faces stays at most one (prepare_coarsening_and_refinement).
  template <int dim>
  std::vector<bool> kelly_refine_flags(LinearElasticProblem<dim> &problem, double cell_fraction);
} // namespace compliant
