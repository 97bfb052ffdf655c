// Linear static analysis of a pin-jointed linkage: the links are separate bodies joined by the
// frictionless pins of "Extra constraints/Pins" (and edge supports), otherwise exactly the
// 'linear static' analysis: the same loads, quantities (Reactions on an eye give the force the
// pin puts on that link and its moment), fields and summary.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis linkage_analysis();
} // namespace compliant
