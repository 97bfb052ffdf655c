// The p-multigrid on the finite-strain Newton tangent.
#include "fast_solver/p_multigrid_solver.templates.h"
#include "fast_solver/tangent_operator.h"

namespace compliant::fast_solver
{
  template class PMultigridSolver<2, TangentOperator<2, double>>;
  template class PMultigridSolver<3, TangentOperator<3, double>>;
} // namespace compliant::fast_solver
