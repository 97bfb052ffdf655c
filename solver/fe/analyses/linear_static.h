// Linear static analysis: one solve of the linear elastic problem, its quantities and fields, on
// the discretization the case sets (the model ladder, ladder/linear_static_analysis.h, decides
// when a target error is asked for).
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  int run_linear_static(const RunContext &context);
} // namespace compliant
