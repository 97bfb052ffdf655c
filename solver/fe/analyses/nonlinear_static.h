// Nonlinear static analysis: finite strain, loads and imposed motions raised in adaptive load
// steps; a step that fails is cut back and retried; response curves written per step.
#pragma once

#include "analyses/analysis.h"

#include <functional>

namespace compliant
{
  struct RunSummary;

  Analysis nonlinear_static_analysis();

  // The analysis itself, for the model ladder's finite-strain rungs: amend_summary, if given,
  // sees the summary (quantities of the last converged step) before it is written and may add
  // to it.
  template <int dim>
  int run_nonlinear_static(const RunContext                             &context,
                           const std::function<void(RunSummary &)> &amend_summary = {});
} // namespace compliant
