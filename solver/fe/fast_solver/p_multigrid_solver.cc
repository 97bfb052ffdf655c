// The p-multigrid on the small-strain elasticity operator (linear static analyses).
#include "fast_solver/elasticity_operator.h"
#include "fast_solver/p_multigrid_solver.templates.h"

namespace compliant::fast_solver
{
  template class PMultigridSolver<2, ElasticityOperator<2, double>>;
  template class PMultigridSolver<3, ElasticityOperator<3, double>>;
} // namespace compliant::fast_solver
