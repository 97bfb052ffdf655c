#include "ladder/adaptive_refinement.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_refinement.h>
#include <deal.II/numerics/error_estimator.h>

#include "analyses/error_estimates.h"
#include "discretization/dof_fingerprint.h"
#include "input/spec_list.h"
#include "quantities/comparison.h"
#include "quantities/goal_functionals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <functional>
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
    Vector<float> kelly_indicators(const Discretization<dim> &problem, const PETScWrappers::MPI::Vector &field)
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
    std::vector<bool> flags_from(Discretization<dim> &problem, const Vector<float> &indicators,
                                 const double cell_fraction)
    {
      auto &triangulation = problem.triangulation;
      // The fraction with the largest indicators, and with them every cell whose indicator ties with
      // the smallest one marked to 1e-5: mirror cells of a symmetric part have equal indicators but
      // for round-off (the solver's tolerance, float), and a tie must not be broken by round-off
      // (refine_and_coarsen_fixed_number marks exact ties only).
      const auto n_marked = static_cast<std::size_t>(cell_fraction * indicators.size());
      if (n_marked > 0)
        {
          std::vector<float> sorted(indicators.begin(), indicators.end());
          std::nth_element(sorted.begin(), sorted.begin() + (n_marked - 1), sorted.end(), std::greater<float>());
          const double threshold = n_marked >= sorted.size() ? std::numeric_limits<double>::lowest() :
                                                               (1 - 1e-5) * sorted[n_marked - 1];
          GridRefinement::refine(triangulation, indicators, threshold);
        }
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
  std::vector<bool> kelly_refine_flags(Discretization<dim> &problem, const PETScWrappers::MPI::Vector &solution,
                                       const double cell_fraction)
  {
    return flags_from(problem, kelly_indicators(problem, solution), cell_fraction);
  }

  namespace
  {
    // How one model's duals are found: the functionals from a linear model of the same mesh
    // (numbered alike), a reaction's right-hand side from its lifting psi, the dual solve, and
    // which functionals hold on this model (at finite strain a small-strain stress does not).
    template <int dim>
    struct DualModel
    {
      Discretization<dim>                    &model; // whose solution and mesh the indicators read
      const PETScWrappers::MPI::Vector       &solution;
      const LinearElasticProblem<dim>        &functionals;
      const AffineConstraints<double>        &held; // the dual's constraints, values zero
      std::function<bool(const std::string &)> holds;
      std::function<PETScWrappers::MPI::Vector(const PETScWrappers::MPI::Vector &psi,
                                               const PETScWrappers::MPI::Vector &linear_j)>
                                                                                       reaction_rhs;
      std::function<PETScWrappers::MPI::Vector(const PETScWrappers::MPI::Vector &rhs)> solve;
      double                                                                           primal_seconds;
    };

    // One dual per target: the right-hand sides of its parts combined by the target's
    // linearization, so that a derived target's dual sees where the errors of its parts cancel
    // (J = M / (G theta') of a bar in torsion depends on the section between the measuring points
    // only).
    template <int dim>
    std::vector<bool> dual_weighted_flags(const DualModel<dim> &m, const std::vector<std::string> &targets,
                                          const Quantities &values, const std::string &derived,
                                          const double cell_fraction, std::string &how)
    {
      const Vector<float> primal = kelly_indicators(m.model, m.solution);
      // Energy-like goals: ||e||_K^2 relative to a(u, u) = 2 U.
      const double  energy = 2 * std::abs(values.count("strain_energy") ? values.at("strain_energy") : 1.0);
      Vector<float> energy_density = primal;
      energy_density.scale(primal);
      Vector<float> indicators(energy_density.size());
      const auto   &owned       = m.functionals.locally_owned_dofs;
      const auto    comm        = m.functionals.communicator;
      how.clear();
      for (const auto &target : targets)
        {
          std::string                used;
          PETScWrappers::MPI::Vector rhs(owned, comm), liftings(owned, comm);
          bool                       has_dual     = false;
          double                     dual_seconds = 0;
          for (const auto &[q, c] : linearization(target, values, derived, m.functionals.expression_variables()))
            {
              PETScWrappers::MPI::Vector j, lifting;
              const bool linear = m.holds(q) && assemble_goal_functional(m.functionals, q, values, m.held, j, lifting);
              if (linear)
                {
                  if (lifting.size() > 0)
                    j = m.reaction_rhs(lifting, j);
                  // A mollified point value is not the point value (a bump cut by the part's faces
                  // averages a smaller lever): scaled to it, so that parts which cancel in the
                  // target still cancel in its dual.
                  const double mollified = lifting.size() == 0 ? j * m.solution : 0.0;
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
              used += (used.empty() ? "" : ", ") + q +
                      (linear ? (lifting.size() > 0 ? " (reaction)" : "") : " (energy-like)");
            }
          if (has_dual)
            {
              // The dual's error is carried by z minus the reactions' liftings (goal_functionals.h).
              Timer                      dual_timer;
              PETScWrappers::MPI::Vector z = m.solve(rhs), dual_error(rhs);
              dual_seconds                 = dual_timer.wall_time();
              dual_error                   = z;
              dual_error.add(-1.0, liftings);
              z                        = dual_error;
              const Vector<float> dual = kelly_indicators(m.model, z);
              for (unsigned int k = 0; k < indicators.size(); ++k)
                indicators[k] += primal[k] * dual[k];
            }
          std::ostringstream cost;
          if (has_dual)
            cost << ", one dual (solved in " << std::setprecision(2) << dual_seconds << " s, the primal's solves in "
                 << m.primal_seconds << " s)";
          how += (how.empty() ? "" : "; ") + target + ": " + used + cost.str();
        }
      return flags_from(m.model, indicators, cell_fraction);
    }

  } // namespace

  template <int dim>
  std::vector<bool> goal_oriented_refine_flags(LinearElasticProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, const double cell_fraction, std::string &how)
  {
    const auto           held = problem.homogeneous_constraints();
    const DualModel<dim> model{problem,
                               problem.solution,
                               problem,
                               held,
                               [](const std::string &) { return true; },
                               [](const PETScWrappers::MPI::Vector &, const PETScWrappers::MPI::Vector &j) { return j; },
                               [&](const PETScWrappers::MPI::Vector &rhs) { return problem.solve_dual(rhs); },
                               problem.statistics.solve_seconds};
    return dual_weighted_flags(model, targets, values, derived, cell_fraction, how);
  }

  template <int dim>
  std::vector<bool> finite_strain_refine_flags(FiniteStrainProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, const double cell_fraction, std::string &how)
  {
    // The functionals come from a linear model of the same case and mesh; its DoFs must be numbered alike.
    CaseParameters linear = problem.parameters;
    linear.analysis       = "linear static";
    LinearElasticProblem<dim> twin(linear, problem.geometry, problem.communicator, problem.mesh_partition);
    std::string               why_not;
    try
      {
        twin.setup();
        if (!numbered_alike(twin.dof_handler, problem.dof_handler, problem.communicator))
          why_not = "a linear model of this mesh numbers its DoFs otherwise";
      }
    catch (const std::exception &e)
      {
        why_not = std::string("no linear model of this case: ") + e.what();
      }
    // A factorization of a large 3D tangent may not fit where Newton chose the matrix-free solver.
    if (why_not.empty() && dim == 3 && problem.matrix_free_tangent() &&
        problem.dof_handler.n_dofs() > max_factored_dual_dofs)
      why_not = "the tangent of " + std::to_string(problem.dof_handler.n_dofs()) +
                " DoFs is not factored for a dual (limit " + std::to_string(max_factored_dual_dofs) + ")";
    if (!why_not.empty())
      {
        how = "Kelly's indicator (" + why_not + ": no finite-strain duals)";
        return flags_from(problem, kelly_indicators(problem, problem.solution), cell_fraction);
      }
    // The finite-strain problem's own constraints at its state (rigid boundaries, contact).
    AffineConstraints<double> held;
    Timer                     factoring;
    const auto                solve          = problem.tangent_dual_solver(held);
    const double              factor_seconds = factoring.wall_time();
    const DualModel<dim>      model{
      problem,
      problem.solution,
      twin,
      held,
      // Small-strain stresses are not the finite-strain ones: those targets are energy-like here.
      [](const std::string &q) { return q.rfind("stress_", 0) != 0 && q.rfind("von_mises_", 0) != 0; },
      [&](const PETScWrappers::MPI::Vector &psi, const PETScWrappers::MPI::Vector &) {
        return problem.tangent_times(psi, held);
      },
      [&](const PETScWrappers::MPI::Vector &rhs) { return solve(rhs); },
      problem.linear_solve_seconds};
    auto               flags = dual_weighted_flags(model, targets, values, derived, cell_fraction, how);
    std::ostringstream factored;
    factored << std::setprecision(2) << factor_seconds;
    how += "; the tangent assembled and factored once for them in " + factored.str() + " s";
    return flags;
  }

  template std::vector<bool> kelly_refine_flags<2>(Discretization<2> &, const PETScWrappers::MPI::Vector &, double);
  template std::vector<bool> kelly_refine_flags<3>(Discretization<3> &, const PETScWrappers::MPI::Vector &, double);
  template std::vector<bool> goal_oriented_refine_flags<2>(LinearElasticProblem<2> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
  template std::vector<bool> goal_oriented_refine_flags<3>(LinearElasticProblem<3> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
  template std::vector<bool> finite_strain_refine_flags<2>(FiniteStrainProblem<2> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
  template std::vector<bool> finite_strain_refine_flags<3>(FiniteStrainProblem<3> &, const std::vector<std::string> &,
                                                           const Quantities &, const std::string &, double, std::string &);
} // namespace compliant
