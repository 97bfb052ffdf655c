// The "linear static" analysis kind: one linear solve as the case sets it (analyses/linear_static.h)
// or, with Target/Relative error > 0, the model ladder, which chooses the model, the discretization
// and, if needed, finite strain. The ladder is a driver above the analyses, so this kind lives here.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis linear_static_analysis();
} // namespace compliant
