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

  // The analysis itself, for the model ladder's finite-strain rungs: amend_summary, if given,
  // sees the summary (quantities of the last converged step) before it is written and may add
  // to it.
  template <int dim>
  int run_nonlinear_static(const RunContext                             &context,
                           const std::function<void(RunSummary &)> &amend_summary = {});
} // namespace compliant
