// The p-multigrid on the small-strain elasticity operator (linear static analyses).
#include "fast_solver/elasticity_operator.h"
#include "fast_solver/p_multigrid_solver.templates.h"

#include <iomanip>
#include <sstream>

namespace compliant::fast_solver
{
  std::string coarse_level_note(const PMultigridStatistics &s)
  {
    if (s.long_edge_dofs > 0)
      return "long-edge space (" + std::to_string(s.long_edge_dofs) + " DoFs) by MUMPS";
    std::string note = std::string("degree-1 level by ") + (s.coarse_direct ? "MUMPS" : "GAMG");
    if (s.thick_part_aspect_ratio > 0)
      {
        std::ostringstream ratio;
        ratio << std::setprecision(3) << s.thick_part_aspect_ratio;
        note += " (no long-edge space: long cells in thick parts, up to " + ratio.str() + ":1)";
      }
    return note;
  }

  template class PMultigridSolver<2, ElasticityOperator<2, double>>;
  template class PMultigridSolver<3, ElasticityOperator<3, double>>;
} // namespace compliant::fast_solver
