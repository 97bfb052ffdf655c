#include "ladder/rung_plan.h"

#include <algorithm>
#include <cmath>

namespace compliant
{
  RungPlan RungPlanner::plan(const unsigned int k) const
  {
    if (!degree_rungs_)
      return {uniform_degree_, k, k > 0};
    const unsigned int h_steps = k + lowest_degree > highest_degree_ ? k + lowest_degree - highest_degree_ : 0;
    return {std::min(k + lowest_degree, highest_degree_), h_steps, h_steps > 0};
  }

  void RungPlanner::simplex_mesh(const bool automatic)
  {
    highest_degree_ = lowest_degree;
    if (automatic && degree_rungs_)
      {
        degree_rungs_   = false;
        uniform_degree_ = lowest_degree;
      }
  }

  double RungPlanner::mesh_size(const bool adaptive, const unsigned int k, const double dofs, const int dim) const
  {
    return adaptive || degree_rungs_ ? std::pow(dofs, -1.0 / dim) : std::ldexp(1.0, -static_cast<int>(k));
  }

  std::string RungPlanner::next_step(const bool adaptive, const unsigned int k) const
  {
    return adaptive                                          ? "refine adaptively:" :
           degree_rungs_ && k + lowest_degree < highest_degree_ ? "raise the degree:" :
                                                                  "refine:";
  }
} // namespace compliant
