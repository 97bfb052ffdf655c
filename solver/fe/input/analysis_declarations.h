// What reading a case needs to know of the analysis kinds: their names, documentation and own
// case-file entries. The application registers every analysis before the first case is read, so
// that input/ (below the analyses) never includes them (ASPECT's plugin registration, by hand).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace compliant
{
  struct AnalysisDeclaration
  {
    std::string name;
    std::string documentation;
    // Declares the analysis' own entries (in its own subsection); may do nothing.
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
  };

  // Adds a kind (a second one of the same name replaces the first).
  void register_analysis(const AnalysisDeclaration &declaration);
  // In registration order; the first is the default of Analysis.
  const std::vector<AnalysisDeclaration> &registered_analyses();
} // namespace compliant
