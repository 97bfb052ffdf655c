// One linear static model built, solved and evaluated, without output: what the 'linear static'
// analysis runs once and the model ladder runs per rung.
#pragma once

#include "analyses/analysis.h"
#include "elasticity/linear_elastic_problem.h"
#include "quantities/quantities.h"

#include <functional>
#include <memory>

namespace compliant
{
  template <int dim>
  struct LinearStaticModel
  {
    std::unique_ptr<LinearElasticProblem<dim>> problem;
    Quantities                                 quantities; // with DoFs, iterations and times
    double                                     seconds = 0; // set-up to quantities
    bool                                       stopped_for_check = false;
  };

  // Case-file mistakes throw InputError naming the case file; with --check it stops after the
  // set-up (stopped_for_check). Prints the mesh and solver lines on rank 0. keep_matrix: the
  // stiffness matrix is assembled and kept (no matrix-free solve), for analyses that go on with it.
  // before_solve, if given, sees the assembled problem just before its solve (the error
  // estimates set a warm start there).
  // The Loads/Pressure a linear model takes: the case's own, or, where it gives none and
  // Finite strain/Follower pressure is set, that pressure on the undeformed boundary (its
  // small-deformation limit: a linear run of a case loaded by a follower pressure alone would
  // otherwise see no load). `substituted` says which.
  std::string linear_pressure(const CaseParameters &parameters, const dealii::ParameterHandler &prm,
                              bool &substituted);

  template <int dim>
  LinearStaticModel<dim> solve_linear_static_model(
    const RunContext &context, const CaseParameters &parameters, bool keep_matrix = false,
    const std::function<void(LinearElasticProblem<dim> &)> &before_solve = {});
} // namespace compliant
