// Linear static analysis: one solve of the linear elastic problem, its quantities and fields.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis linear_static_analysis();
} // namespace compliant
