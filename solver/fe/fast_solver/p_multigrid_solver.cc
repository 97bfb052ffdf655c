// The p-multigrid on the small-strain elasticity operator (linear static analyses).
#include "fast_solver/elasticity_operator.h"
#include "fast_solver/p_multigrid_solver.templates.h"

namespace compliant::fast_solver
{
  std::string coarse_level_note(const PMultigridStatistics &s)
  {
    if (s.long_edge_dofs > 0)
      return "long-edge space (" + std::to_string(s.long_edge_dofs) + " DoFs) by MUMPS";
    return std::string("degree-1 level by ") + (s.coarse_direct ? "MUMPS" : "GAMG");
  }

  template class PMultigridSolver<2, ElasticityOperator<2, double>>;
  template class PMultigridSolver<3, ElasticityOperator<3, double>>;
} // namespace compliant::fast_solver
