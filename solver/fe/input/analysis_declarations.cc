#include "input/analysis_declarations.h"

namespace compliant
{
  namespace
  {
    std::vector<AnalysisDeclaration> &registry()
    {
      static std::vector<AnalysisDeclaration> list;
      return list;
    }
  } // namespace

  void register_analysis(const AnalysisDeclaration &declaration)
  {
    for (auto &existing : registry())
      if (existing.name == declaration.name)
        {
          existing = declaration;
          return;
        }
    registry().push_back(declaration);
  }

  const std::vector<AnalysisDeclaration> &registered_analyses() { return registry(); }
} // namespace compliant
