#include "analyses/setup_without_supports.h"

#include <deal.II/base/timer.h>

#include "input/spec_list.h"

namespace compliant
{
  using namespace dealii;

  bool has_supports(const CaseParameters &p)
  {
    return !trim(p.clamped).empty() || !trim(p.displacement).empty() || !trim(p.rotation).empty();
  }

  template <int dim>
  void setup_without_supports(LinearElasticProblem<dim> &problem)
  {
    Timer timer;
    problem.setup_discretization();
    // The sparsity pattern and the matrix follow in install_constraints().
    problem.statistics.setup_seconds = timer.wall_time();
  }

  template void setup_without_supports<2>(LinearElasticProblem<2> &);
  template void setup_without_supports<3>(LinearElasticProblem<3> &);
} // namespace compliant
