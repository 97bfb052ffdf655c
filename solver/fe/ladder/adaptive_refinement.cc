#include "ladder/adaptive_refinement.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include "analyses/error_estimates.h"
#include "input/spec_list.h"
#include "quantities/comparison.h"
#include "quantities/goal_functionals.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <map>
#include <set>

namespace compliant
{
  namespace
  {
    using namespace dealii;

    // Kelly's indicator of a field of this problem's DoFs, on every cell on every rank.
    template <int dim>
    Vector<float> kelly_indicators(const LinearElasticProblem<dim> &problem, const PETScWrappers::MPI::Vector &field)
    {
      const auto    &triangulation = problem.triangulation;
      Vector<float>  indicators(triangulation.n_active_cells());
      // Each rank estimates its own cells (the others stay 0); the sum gives every rank all of them.
      KellyErrorEstimator<dim>::estimate(*problem.mapping, problem.dof_handler, *problem.face_quadrature,
                                         std::map<types::boundary_id, const Function<dim> *>(), field, indicators,
                                         ComponentMask(), nullptr, numbers::invalid_unsigned_int,
                                         triangulation.locally_owned_subdomain());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (!cell->is_locally_owned())
          indicators[cell->active_cell_index()] = 0;
      Utilities::MPI::sum(indicators, problem.communicator, indicators);
      return indicators;
    }

    template <int dim>
    std::vector<bool> flags_from(LinearElasticProblem<dim> &problem, const Vector<float> &indicators,
                                 const double cell_fraction)
    {
      auto &triangulation = problem.triangulation;
      GridRefinement::refine_and_coarsen_fixed_number(triangulation, indicators, cell_fraction, 0.0);
      triangulation.prepare_coarsening_and_refinement();
      std::vector<bool> flags;
      triangulation.save_refine_flags(flags);
      for (const auto &cell : triangulation.active_cell_iterators())
        cell->clear_refine_flag();
      return flags;
    }

    // The linearization of target J in the quantities it depends on, relative: c_q = (dJ/dq) / J,
    // signed, so that dJ / J = sum_q c_q dq (errors of parts that cancel in J cancel in its dual).
    // 1 / J for J itself unless J is derived, then by central differences of the Derived expressions.
    std::map<std::string, double> linearization(const std::string &target, const Quantities &values,
                                                const std::string &derived, const std::map<std::string, double> &variables)
    {
      const double value = values.count(target) ? values.at(target) : 1.0;
      const std::map<std::string, double> itself{{target, 1 / (value != 0 ? value : 1.0)}};
      // The names the expressions define ('name = expression; ...') are not base quantities.
      std::set<std::string> defined;
      for (const auto &item : split(derived, ';'))
        if (const auto equals = item.find('='); equals != std::string::npos)
          defined.insert(trim(item.substr(0, equals)));
      Quantities base;
      for (const auto &[n, v] : values)
        if (has_error_estimate(n) && defined.count(n) == 0)
          base[n] = v;
      Quantities evaluated = base;
      try
        {
          add_derived_quantities(derived, evaluated, variables);
        }
      catch (const std::invalid_argument &)
        {
          return itself;
        }
      // A target the expressions do not produce is a computed quantity.
      if (derived.find(target) == std::string::npos || base.count(target) > 0 || evaluated.count(target) == 0)
        return itself;
      const double                  j = evaluated.at(target);
      std::map<std::string, double> c;
      for (const auto &[n, v] : base)
        if (derived.find(n) != std::string::npos)
          {
            const double h = 1e-6 * std::max(std::abs(v), 1e-300);
            Quantities   plus = base, minus = base;
            plus[n] += h, minus[n] -= h;
            add_derived_quantities(derived, plus, variables);
            add_derived_quantities(derived, minus, variables);
            const double derivative = (plus.at(target) - minus.at(target)) / (2 * h);
            if (std::isfinite(derivative) && derivative != 0 && j != 0)
              c[n] = derivative / j;
          }
      return c.empty() ? itself : c;
    }
  } // namespace

  template <int dim>
  std::vector<bool> kelly_refine_flags(LinearElasticProblem<dim> &problem, const double cell_fraction)
  {
    return flags_from(problem, kelly_indicators(problem, problem.solution), cell_fraction);
  }

  // One dual per target: the right-hand sides of its parts combined by the target's linearization,
  // so that a derived target's dual sees where the errors of its parts cancel (J = M / (G theta')
  // of a bar in torsion depends on the section between the measuring points only).
  template <int dim>
  std::vector<bool> goal_oriented_refine_flags(LinearElasticProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, const double cell_fraction, std::string &how)
  {
    const Vector<float> primal = kelly_indicators(problem, problem.solution);
    // Energy-like goals: ||e||_K^2 relative to a(u, u) = 2 U.
    const double energy = 2 * std::abs(values.count("strain_energy") ? values.at("strain_energy") : 1.0);
    Vector<float> energy_density = primal;
    energy_density.scale(primal);
    Vector<float> indicators(energy_density.size());
    const auto    homogeneous = problem.homogeneous_constraints();
    how.clear();
    for (const auto &target : targets)
      {
        std::string                used;
        PETScWrappers::MPI::Vector rhs(problem.locally_owned_dofs, problem.communicator);
        PETScWrappers::MPI::Vector liftings(problem.locally_owned_dofs, problem.communicator);
        bool                       has_dual = false;
        double                     dual_seconds = 0;
        for (const auto &[q, c] : linearization(target, values, derived, problem.expression_variables()))
          {
            PETScWrappers::MPI::Vector j, lifting;
            const bool linear = assemble_goal_functional(problem, q, values, homogeneous, j, lifting);
            if (linear)
              {
                // A mollified point value is not the point value (a bump cut by the part's faces
                // averages a smaller lever): scaled to it, so that parts which cancel in the
                // target still cancel in its dual.
                const double mollified = lifting.size() == 0 ? j * problem.solution : 0.0;
                const double value     = values.count(q) ? values.at(q) : 0.0;
                if (mollified != 0 && value / mollified > 0.1 && value / mollified < 10)
                  j *= value / mollified;
                rhs.add(c, j);
                if (lifting.size() > 0)
                  liftings.add(c, lifting);
                has_dual = true;
              }
            else
              indicators.add(std::abs(c * (values.count(q) ? values.at(q) : 1.0)) / energy, energy_density);
            used += (used.empty() ? "" : ", ") + q + (linear ? (lifting.size() > 0 ? " (reaction)" : "") : " (energy-like)");
          }
        if (has_dual)
          {
            // The dual's error is carried by z minus the reactions' liftings (goal_functionals.h).
            Timer                      dual_timer;
            PETScWrappers::MPI::Vector z = problem.solve_dual(rhs), dual_error(rhs);
            dual_seconds                 = dual_timer.wall_time();
            dual_error = z;
            dual_error.add(-1.0, liftings);
            z = dual_error;
            const Vector<float> dual = kelly_indicators(problem, z);
            for (unsigned int k = 0; k < indicators.size(); ++k)
              indicators[k] += primal[k] * dual[k];
          }
        std::ostringstream cost;
        if (has_dual)
          cost << ", one dual (solved in " << std::setprecision(2) << dual_seconds << " s, the primal in "
               << problem.statistics.solve_seconds << " s)";
        how += (how.empty() ? "" : "; ") + target + ": " + used + cost.str();
      }
    return flags_from(problem, indicators, cell_fraction);
  }

  template std::vector<bool> kelly_refine_flags<2>(LinearElasticProblem<2> &, double);
  template std::vector<bool> kelly_refine_flags<3>(LinearElasticProblem<3> &, double);
  template std::vector<bool> goal_oriented_refine_flags<2>(LinearElasticProblem<2> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
  template std::vector<bool> goal_oriented_refine_flags<3>(LinearElasticProblem<3> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
} // namespace compliant
