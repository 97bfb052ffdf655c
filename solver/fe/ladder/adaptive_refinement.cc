#include "ladder/adaptive_refinement.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include <map>

namespace compliant
{
  template <int dim>
  std::vector<bool> kelly_refine_flags(LinearElasticProblem<dim> &problem, const double cell_fraction)
  {
    using namespace dealii;
    auto          &triangulation = problem.triangulation;
    Vector<float>  indicators(triangulation.n_active_cells());
    // Each rank estimates its own cells (the others stay 0); the sum gives every rank all of them.
    KellyErrorEstimator<dim>::estimate(*problem.mapping, problem.dof_handler, *problem.face_quadrature,
                                       std::map<types::boundary_id, const Function<dim> *>(),
                                       problem.solution, indicators, ComponentMask(), nullptr,
                                       numbers::invalid_unsigned_int, triangulation.locally_owned_subdomain());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (!cell->is_locally_owned())
        indicators[cell->active_cell_index()] = 0;
    Utilities::MPI::sum(indicators, problem.communicator, indicators);
    GridRefinement::refine_and_coarsen_fixed_number(triangulation, indicators, cell_fraction, 0.0);
    triangulation.prepare_coarsening_and_refinement();
    std::vector<bool> flags;
    triangulation.save_refine_flags(flags);
    for (const auto &cell : triangulation.active_cell_iterators())
      cell->clear_refine_flag();
    return flags;
  }

  template std::vector<bool> kelly_refine_flags<2>(LinearElasticProblem<2> &, double);
  template std::vector<bool> kelly_refine_flags<3>(LinearElasticProblem<3> &, double);
} // namespace compliant
