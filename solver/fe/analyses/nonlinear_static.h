// Nonlinear static analysis: finite strain, loads and imposed motions raised in adaptive load
// steps; a step that fails is cut back and retried; response curves written per step.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis nonlinear_static_analysis();
} // namespace compliant
