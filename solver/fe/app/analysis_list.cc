#include "app/analysis_list.h"

#include "analyses/buckling.h"
#include "analyses/linkage.h"
#include "analyses/modal.h"
#include "analyses/nonlinear_static.h"
#include "ladder/linear_static_analysis.h"

namespace compliant
{
  const std::vector<Analysis> &analyses()
  {
    static const std::vector<Analysis> list = {linear_static_analysis(), nonlinear_static_analysis(),
                                               modal_analysis(), buckling_analysis(), linkage_analysis()};
    return list;
  }

  void register_analyses()
  {
    for (const auto &a : analyses())
      register_analysis(a);
  }

  const Analysis &find_analysis(const std::string &name)
  {
    for (const auto &a : analyses())
      if (a.name == name)
        return a;
    throw InputError("unknown analysis '" + name + "'");
  }
} // namespace compliant
