// (d) in finite strain, when the linear answer's geometric error misses the target: from the
// case's own mesh, uniform refinement at the case's degree, degree rungs as in the linear climb
// when Refinement = degree asks for them, or adaptive refinement (Refinement = adaptive) by the
// duals of the tangent at each rung's converged state (ladder/adaptive_refinement.h), until the
// estimate meets the target. Auto stays uniform here: the tangent is assembled cell by cell,
// whose cost grows steeply with the degree (3D roll-up, degrees 2, 3, 4: 2.9, 22, 130 s for 2.7k,
// 7.2k, 15k DoFs). Every rung writes the output directory; what stays is the last rung's, with
// its estimates.
#include "analyses/nonlinear_static.h"
#include "ladder/adaptive_refinement.h"
#include "ladder/ladder_climb.h"
#include "quantities/comparison.h"
#include "mesh/memory_estimate.h"

#include <iostream>

namespace compliant
{
  template <int dim>
  int LadderClimb<dim>::climb_finite_strain()
  {
    chosen.problem.reset();
    const RungPlanner fs_planner(target.degree, planner.uniform_degree(), planner.highest_degree());
    stop_rule.restart();
    std::map<std::string, std::vector<double>> history;
    std::vector<double>                        sizes;
    bool                                       fs_met     = false;
    double                                     last_cells = 0;
    // Adaptive rungs: each refines the last one's mesh where the duals at its state point.
    const bool                     adaptive = target.adaptive;
    std::vector<std::vector<bool>> refinements;
    for (unsigned int j = 0; j <= target.max_refinements && !fs_met; ++j)
      {
        const RungPlan     plan = fs_planner.plan(adaptive ? 0 : j);
        const unsigned int r    = p.global_refinements + plan.h_steps;
        if (j > 0 && !adaptive)
          try
            {
              refuse_refinement_beyond_memory(static_cast<std::uint64_t>(last_cells), dim, plan.refines_cells ? 1 : 0,
                                              plan.degree,
                                              dealii::Utilities::MPI::n_mpi_processes(context.communicator));
            }
          catch (const ModelTooLarge &e)
            {
              too_large             = e.what();
              rungs.back().decision = "target NOT met: the next rung would not fit in memory";
              if (root)
                std::cout << "  (d) no finite-strain rung at degree " << plan.degree << ", " << r
                          << " refinements: " << too_large << std::endl;
              break;
            }
        CaseParameters nonlinear     = *chosen_parameters;
        nonlinear.analysis           = "nonlinear static";
        nonlinear.pressure           = p.pressure; // the case's own (linear rungs may carry the follower's)
        nonlinear.element_degree     = plan.degree;
        nonlinear.global_refinements = r;
        if (adaptive)
          {
            nonlinear.mesh_partition       = PartitionRequest::shared; // the flags cover the whole mesh
            nonlinear.adaptive_refinements = refinements;
          }
        const RunContext nonlinear_context{nonlinear, context.prm, context.geometry, context.check_only,
                                           context.communicator};
        Rung rung;
        rung.model           = "finite strain";
        rung.degree          = plan.degree;
        rung.refinements     = r;
        rung.adaptive_cycles = refinements.size();
        dealii::Timer rung_timer;
        // The estimates join the rung's summary before it is written.
        const auto amend = [&](RunSummary &summary, FiniteStrainProblem<dim> &problem) {
          rung.dofs  = summary.quantities.at("n_dofs");
          last_cells = summary.quantities.at("n_cells");
          sizes.push_back(fs_planner.mesh_size(adaptive, j, rung.dofs, dim));
          fs_met = true;
          for (const auto &n : names)
            {
              const auto found = summary.quantities.find(n);
              if (found == summary.quantities.end())
                throw InputError("case file '" + p.case_file + "', Target/Quantities: '" + n +
                                 "' is not a reported quantity of the finite-strain analysis");
              history[n].push_back(found->second);
              const double attainable = fs_planner.degree_rungs() ? 0 : attainable_order(plan.degree);
              const auto   e = estimate_discretization_error(history[n], sizes, plan.degree + 1.0, attainable);
              rung.values[n]         = found->second;
              rung.estimates[n]      = e;
              const double stop      = stop_rule.stop_estimate(n, e, adaptive || fs_planner.degree_rungs());
              rung.stop_estimates[n] = stop;
              fs_met                 = fs_met && stop >= 0 && stop <= target.relative_error;
            }
          add_estimates_to_summary(summary, rung);
          // Only from a completed path: a failed one's state is not the one the target asks about.
          if (adaptive && !fs_met && j < target.max_refinements && summary.settings.at("status") == "completed")
            refinements.push_back(finite_strain_flags(problem, summary));
          summary.settings.insert({"ladder", fs_met ? "target met" : "target not met"});
          summary.settings.insert({"ladder_geometric_check", geometric_reason});
          if (out_of_plane >= 0)
            {
              summary.settings.insert({"ladder_dimension_check", dimension_reason + " (linear rung)"});
              summary.quantities["out_of_plane_bound"] = out_of_plane;
            }
          summary.quantities["ladder_rungs"]          = rungs.size() + 1 + earlier_rows.size();
          summary.quantities["ladder_total_seconds"]  = total.wall_time() + target.earlier_seconds;
          summary.quantities["target_relative_error"] = target.relative_error;
        };
        const int rc = run_nonlinear_static<dim>(nonlinear_context, amend);
        rung.seconds = rung_timer.wall_time();
        if (rc != 0)
          {
            if (!rung.values.empty())
              rungs.push_back(rung);
            if (root)
              write_ladder_csv(nonlinear.output_directory, names, all_rows());
            return rc;
          }
        if (fs_met)
          rung.decision = "estimate meets the target: stop";
        else if (j == target.max_refinements)
          rung.decision = "target NOT met within Target/Maximum refinements";
        else
          rung.decision = fs_planner.next_step(adaptive, j) + stop_rule.why_go_on(rung.estimates, target.relative_error);
        print(rung);
        rungs.push_back(rung);
      }
    if (root)
      write_ladder_csv(chosen_parameters->output_directory, names, all_rows());
    return fs_met ? 0 : 4;
  }

  template <int dim>
  std::vector<bool> LadderClimb<dim>::finite_strain_flags(FiniteStrainProblem<dim> &problem, const RunSummary &summary)
  {
    if (!target.goal_oriented)
      return kelly_refine_flags<dim>(problem, problem.solution, target.refined_fraction);
    auto values = summary.quantities;
    add_derived_quantities(p.derived, values, problem.expression_variables());
    std::string       how;
    std::vector<bool> flags;
    try
      {
        flags = finite_strain_refine_flags(problem, names, values, p.derived, target.refined_fraction, how);
      }
    catch (const std::exception &e) // a singular tangent at a limit point, an inverted cell
      {
        how   = std::string("Kelly's indicator (the duals failed: ") + e.what() + ")";
        flags = kelly_refine_flags<dim>(problem, problem.solution, target.refined_fraction);
      }
    if (root)
      std::cout << "  (d) refine for " << how << " (duals of the tangent at the converged state)" << std::endl;
    return flags;
  }

  template int LadderClimb<2>::climb_finite_strain();
  template int LadderClimb<3>::climb_finite_strain();
  template std::vector<bool> LadderClimb<2>::finite_strain_flags(FiniteStrainProblem<2> &, const RunSummary &);
  template std::vector<bool> LadderClimb<3>::finite_strain_flags(FiniteStrainProblem<3> &, const RunSummary &);
} // namespace compliant
