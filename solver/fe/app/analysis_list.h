// Every analysis kind of the executable, in the order --help lists them: adding an analysis is
// its folder plus one line in analysis_list.cc.
#pragma once

#include "analyses/analysis.h"

#include <string>
#include <vector>

namespace compliant
{
  const std::vector<Analysis> &analyses();
  // Registers every kind's declarations for case reading (input/analysis_declarations.h).
  void register_analyses();
  const Analysis &find_analysis(const std::string &name);
} // namespace compliant
