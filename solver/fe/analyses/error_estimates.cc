#include "analyses/error_estimates.h"

#include <deal.II/base/timer.h>

#include "discretization/degree_transfer.h"
#include "fast_solver/coarse_level_solver.h"
#include "mesh/memory_estimate.h"
#include "quantities/comparison.h"

#include <cmath>
#include <set>
#include <tuple>
#include <iostream>
#include <sstream>

namespace compliant
{
  bool has_error_estimate(const std::string &name)
  {
    const auto starts = [&](const std::string &prefix) { return name.rfind(prefix, 0) == 0; };
    const auto ends   = [&](const std::string &suffix) {
      return name.size() >= suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (starts("n_") || starts("time_") || starts("solver_") || starts("eigen") || ends("_error_estimate") ||
        ends("_error_estimate_absolute") || starts("error_estimate_") || starts("contact_nodes_") ||
        starts("contact_sticking_nodes_") || starts("contact_slipping_nodes_"))
      return false;
    // A path's counts and where it stands are not values of the model to converge.
    static const std::set<std::string> path_records = {
      "load_factor", "load_steps", "step_cutbacks", "newton_iterations", "linear_solves", "linear_iterations",
      "preconditioner_builds", "contact_active_nodes", "contact_max_penetration", "contact_penetration_tolerance",
      "last_stable_load_factor", "limit_points", "bifurcations"};
    if (path_records.count(name) != 0)
      return false;
    // Where a peak lies (max_von_mises_x, max_von_mises_in_<body>_x) is a place, not a value to converge.
    if (starts("max_") && (ends("_x") || ends("_y") || ends("_z")))
      return false;
    return true;
  }

  template <int dim>
  QuantityEstimates estimate_quantity_errors(const RunContext &context, const CaseParameters &parameters,
                                             const Quantities &values, const bool hypercube_cells,
                                             const EnrichedSolve &solve, const LinearElasticProblem<dim> *primal)
  {
    const bool        root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
    QuantityEstimates estimates;
    CaseParameters    enriched = parameters;
    // Simplices stop at degree 2, the hexahedral kernels at 4: past that, refine once instead.
    const bool by_degree = parameters.element_degree < (hypercube_cells ? 4u : 2u);
    if (by_degree)
      {
        enriched.element_degree = parameters.element_degree + 1;
        if (primal)
          enriched.mesh_partition = partition_of_model(primal->mesh_partition.partition);
      }
    else
      enriched.global_refinements = parameters.global_refinements + 1;
    estimates.dual_degree = enriched.element_degree;
    estimates.how = by_degree ? "dual at degree " + std::to_string(enriched.element_degree) + " on the same mesh" :
                                "dual on the once-refined mesh at degree " + std::to_string(enriched.element_degree) +
                                  " (the highest this element has)";
    try
      {
        refuse_refinement_beyond_memory(static_cast<std::uint64_t>(values.at("n_cells")), dim, by_degree ? 0 : 1,
                                        enriched.element_degree,
                                        dealii::Utilities::MPI::n_mpi_processes(context.communicator));
      }
    catch (const ModelTooLarge &e)
      {
        estimates.how = "not computed: the enriched model would not fit in memory (" + std::string(e.what()) + ")";
        if (root)
          std::cout << "Error estimates: " << estimates.how << std::endl;
        return estimates;
      }
    if (root)
      std::cout << "Error estimates: " << estimates.how << " (one enriched solve for every quantity)" << std::endl;
    dealii::Timer    timer;
    const RunContext enriched_context{enriched, context.prm, context.geometry, false, context.communicator};
    Quantities       plus;
    if (solve)
      std::tie(plus, estimates.dual_dofs) = solve(enriched_context, enriched);
    else
      {
        const std::function<void(LinearElasticProblem<dim> &)> warm_start = [&](LinearElasticProblem<dim> &problem) {
          if (!primal)
            return;
          problem.warm_start_reduction = enriched_solve_reduction;
          if (!by_degree)
            {
              // Simplices at degree 2: two-level CG from the unrefined model, its MUMPS factor below
              // (whether it ran is read from the solve afterwards).
              problem.coarse_twin = primal;
              return;
            }
          if (problem.solver_method != SolverMethod::matrix_free)
            return;
          estimates.warm_started =
            interpolate_to_finer_degree<dim>(*primal, primal->solution, problem, problem.warm_start);
          problem.reused_degree_one_level = primal->degree_one_level;
          problem.reused_lower_multigrid  = primal->multigrid;
          // A degree-1 model solved by MUMPS: its factor is the degree-2 multigrid's exact coarse solve.
          if (!problem.reused_degree_one_level && primal->factorization && primal->fe->degree == 1 &&
              primal->solver_method == SolverMethod::direct)
            problem.reused_degree_one_level =
              fast_solver::degree_one_level_from_factor<dim>(primal->dof_handler, primal->homogeneous_constraints(),
                                                             primal->factorization,
                                                             primal->communicator);
        };
        auto model = solve_linear_static_model<dim>(enriched_context, enriched, false, warm_start);
        plus       = model.quantities;
        estimates.dual_solve_seconds = model.problem->statistics.solve_seconds;
        estimates.dual_iterations    = model.problem->statistics.iterations;
        if (model.problem->coarse_twin)
          estimates.warm_started = model.problem->solver_note.rfind("two-level CG", 0) == 0;
        if (estimates.warm_started && !by_degree)
          {
            std::ostringstream reduction;
            reduction << enriched_solve_reduction;
            estimates.how += ", solved by two-level CG from the model's solution (the model's MUMPS factor as "
                             "its coarse level) to a residual reduction of " + reduction.str();
          }
        else if (estimates.warm_started)
          {
            std::ostringstream reduction;
            reduction << enriched_solve_reduction;
            estimates.how += ", solved from the degree-p solution to a residual reduction of " + reduction.str();
          }
        if (model.problem->statistics.lower_multigrid_reused)
          estimates.how += ", its multigrid the model's own below degree p + 1 (levels, smoothers, degree-1 level)";
        else if (model.problem->statistics.degree_one_reused)
          estimates.how += primal && primal->fe->degree == 1 ?
                             (primal->solver_method == SolverMethod::direct ?
                                ", its multigrid's degree-1 level the model's own matrix and MUMPS factor" :
                                ", its multigrid's degree-1 level the model's own matrix and GAMG") :
                             ", its multigrid's degree-1 level (matrix and AMG) the model's own";
        try
          {
            add_derived_quantities(parameters.derived, plus, model.problem->expression_variables());
          }
        catch (const std::invalid_argument &e)
          {
            throw InputError("case file '" + parameters.case_file + "', Quantities/Derived: " + e.what());
          }
        estimates.dual_dofs = model.problem->dof_handler.n_dofs();
      }
    if (plus.empty())
      {
        estimates.how = "not computed: the enriched model did not complete the same path";
        if (root)
          std::cout << "Error estimates: " << estimates.how << std::endl;
        return estimates;
      }
    estimates.available    = true;
    estimates.dual_seconds = timer.wall_time();
    // A component that is round-off next to its siblings (displacement_outer_y of a radial
    // displacement, 1e-22 beside 0.03) has no relative error: the absolute estimate only.
    std::map<std::string, double> family_scale;
    const auto family = [](const std::string &name) { return name.substr(0, name.rfind('_')); };
    for (const auto &[name, value] : values)
      family_scale[family(name)] = std::max(family_scale[family(name)], std::abs(value));
    for (const auto &[name, value] : values)
      if (const auto found = plus.find(name); found != plus.end() && has_error_estimate(name) &&
                                              std::isfinite(value) && std::isfinite(found->second))
        {
          const double difference  = std::abs(found->second - value);
          estimates.absolute[name] = difference;
          if (std::abs(value) > 1e-8 * family_scale[family(name)])
            estimates.relative[name] = difference / std::abs(value);
        }
    return estimates;
  }

  void add_error_estimates(RunSummary &summary, const QuantityEstimates &estimates)
  {
    for (const auto &[name, absolute] : estimates.absolute)
      {
        if (const auto relative = estimates.relative.find(name); relative != estimates.relative.end())
          summary.quantities[name + "_error_estimate"] = relative->second;
        summary.quantities[name + "_error_estimate_absolute"] = absolute;
      }
    summary.settings.insert({"error_estimates", estimates.available ?
                                                  "dual-weighted residual, " + estimates.how + ": J(u+) - J(u)" :
                                                  estimates.how});
    if (estimates.available)
      {
        summary.quantities["error_estimate_dofs"] = estimates.dual_dofs;
        summary.quantities["time_error_estimate"] = estimates.dual_seconds;
        summary.quantities["time_error_estimate_solve"] = estimates.dual_solve_seconds;
        summary.quantities["error_estimate_iterations"] = estimates.dual_iterations;
      }
  }

  template QuantityEstimates estimate_quantity_errors<2>(const RunContext &, const CaseParameters &,
                                                         const Quantities &, bool, const EnrichedSolve &,
                                                         const LinearElasticProblem<2> *);
  template QuantityEstimates estimate_quantity_errors<3>(const RunContext &, const CaseParameters &,
                                                         const Quantities &, bool, const EnrichedSolve &,
                                                         const LinearElasticProblem<3> *);
} // namespace compliant
