#include "ladder/stop_rule.h"

#include "ladder/percent.h"

#include <algorithm>

namespace compliant
{
  std::string StopRule::safety_factor_text() const
  {
    return std::to_string(static_cast<int>(safety_factor()));
  }

  double StopRule::stop_estimate(const std::string &name, const ErrorEstimate &e, const bool uneven)
  {
    bool steady = true;
    if (uneven)
      {
        const double previous = orders[name];
        steady = e.order_observed && previous > 0 &&
                 std::max(previous, e.observed_order) < 1.5 * std::min(previous, e.observed_order);
        orders[name] = e.order_observed ? e.observed_order : 0;
        if (!steady && e.available)
          unsteady[name] = previous > 0 && e.order_observed ?
                             "observed order not steady yet (" + std::to_string(previous).substr(0, 4) +
                               " then " + std::to_string(e.observed_order).substr(0, 4) + ")" :
                             "observed order not steady yet";
        else
          unsteady.erase(name);
      }
    return e.available && e.order_observed ? (steady ? 1 : safety_factor()) * e.relative : -1.0;
  }

  std::string StopRule::why_go_on(const std::map<std::string, ErrorEstimate> &estimates, const double target) const
  {
    std::string why;
    for (const auto &[n, e] : estimates)
      if (!e.available)
        why += " " + n + " " + e.note + ";";
      else if (e.relative > target)
        why += " " + n + " estimate " + percent(e.relative) + " > target;";
      else if (!e.order_observed)
        why += " " + n + " " + e.note + ", one more rung to observe it;";
      else if (const auto u = unsteady.find(n); u != unsteady.end())
        why += " " + n + " " + u->second + " and " + safety_factor_text() + " x estimate > target;";
    return why;
  }

  void StopRule::restart()
  {
    orders.clear();
    unsteady.clear();
  }
} // namespace compliant
