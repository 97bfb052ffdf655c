#include "ladder/adaptive_refinement.h"

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include "analyses/error_estimates.h"
#include "input/spec_list.h"
#include "quantities/comparison.h"
#include "quantities/goal_functionals.h"

#include <cmath>
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

    // The relative sensitivity |dJ/dq q / J| of target J to each quantity q it depends on: 1 for
    // J itself unless J is derived, then by central differences of the Derived expressions.
    std::map<std::string, double> sensitivities(const std::string &target, const Quantities &values,
                                                const std::string &derived, const std::map<std::string, double> &variables)
    {
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
          return {{target, 1.0}};
        }
      // A target the expressions do not produce is a computed quantity.
      if (derived.find(target) == std::string::npos || base.count(target) > 0 || evaluated.count(target) == 0)
        return {{target, 1.0}};
      const double                  j = evaluated.at(target);
      std::map<std::string, double> s;
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
              s[n] = std::abs(derivative * v / j);
          }
      return s.empty() ? std::map<std::string, double>{{target, 1.0}} : s;
    }
  } // namespace

  template <int dim>
  std::vector<bool> kelly_refine_flags(LinearElasticProblem<dim> &problem, const double cell_fraction)
  {
    return flags_from(problem, kelly_indicators(problem, problem.solution), cell_fraction);
  }

  template <int dim>
  std::vector<bool> goal_oriented_refine_flags(LinearElasticProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, const double cell_fraction, std::string &how)
  {
    const Vector<float> primal = kelly_indicators(problem, problem.solution);
    // Energy-like goals: ||e||_K^2 relative to a(u, u) = 2 U.
    const double energy = 2 * std::abs(values.count("strain_energy") ? values.at("strain_energy") : 1.0);
    Vector<float>   indicators(primal.size());
    const auto      homogeneous = problem.homogeneous_constraints();
    std::map<std::string, Vector<float>> dual_indicators; // one dual per quantity, however many targets use it
    how.clear();
    for (const auto &target : targets)
      {
        std::string used;
        for (const auto &[q, weight] : sensitivities(target, values, derived, problem.expression_variables()))
          {
            if (dual_indicators.count(q) == 0)
              {
                PETScWrappers::MPI::Vector j;
                if (assemble_goal_functional(problem, q, values, homogeneous, j))
                  dual_indicators[q] = kelly_indicators(problem, problem.solve_dual(j));
                else
                  dual_indicators[q] = Vector<float>(); // energy-like
              }
            const auto  &dual  = dual_indicators.at(q);
            const double value = std::max(std::abs(values.count(q) ? values.at(q) : 1.0), 1e-300);
            for (unsigned int k = 0; k < indicators.size(); ++k)
              indicators[k] += weight * (dual.size() > 0 ? primal[k] * dual[k] / value : primal[k] * primal[k] / energy);
            used += (used.empty() ? "" : ", ") + q + (dual.size() > 0 ? " (dual)" : " (energy-like)");
          }
        how += (how.empty() ? "" : "; ") + target + ": " + used;
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
