// Nonlinear static analysis: finite strain, loads and imposed motions raised in adaptive load
// steps; a step that fails is cut back and retried; response curves written per step.
#pragma once

#include "analyses/analysis.h"
#include "finite_strain/finite_strain_problem.h"
#include "nonlinear/arc_length.h"
#include "nonlinear/load_stepping.h"

#include <functional>

namespace compliant
{
  struct RunSummary;

  Analysis nonlinear_static_analysis();

  // Subsection Finite strain, read once: the law, the load steps, the arc length.
  struct PathSettings
  {
    FiniteStrainSettings finite_strain;
    LoadSteppingSettings stepping;
    ArcLengthSettings    continuation;
    bool                 arc_length = false;
  };
  PathSettings read_path_settings(dealii::ParameterHandler &prm, const CaseParameters &p, int dim);

  // Sees the summary (quantities of the last converged step) before it is written, with the
  // problem at that state, and may add to it (and mark the problem's cells for refinement).
  template <int dim>
  using SummaryAmendment = std::function<void(RunSummary &, FiniteStrainProblem<dim> &)>;

  // The analysis itself, for the model ladder's finite-strain rungs and the error estimates.
  // start_from, if given, is a converged problem of the same case on the same mesh at a lower
  // degree: its state is carried to this run's space and Newton solves at its load factor, so
  // the run ends in the same state of a hyperelastic body without following the path again (the
  // estimates' enriched model). Where the state cannot be carried (another mesh or partition)
  // or Newton fails from it, the run follows the path.
  template <int dim>
  int run_nonlinear_static(const RunContext &context, const SummaryAmendment<dim> &amend_summary = {},
                           const FiniteStrainProblem<dim> *start_from = nullptr);

  // The analysis with Quantities/Error estimates: the run, then its enriched model (degree p + 1)
  // from the run's end state (nonlinear_static_estimates.cc).
  template <int dim>
  int run_nonlinear_static_with_estimates(const RunContext &context);
} // namespace compliant
