// The ladder's linear rungs: (d) refinement until the stop rule is met, with (b) the plane-stress
// model's out-of-plane bound on every rung and (c) the linear/finite-strain decision after the
// first; then the chosen linear model's output.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include "analyses/error_estimates.h"
#include "analyses/nonlinear_static.h"
#include "ladder/adaptive_refinement.h"
#include "ladder/ladder_climb.h"
#include "ladder/percent.h"
#include "ladder/model_checks.h"
#include "mesh/memory_estimate.h"
#include "output/field_output.h"
#include "output/run_pictures.h"
#include "quantities/comparison.h"
#include "quantities/out_of_plane_bound.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

namespace compliant
{
  namespace
  {
    // Largest rotation of material lines, |skew(grad u)| (radians, infinitesimal), over the
    // quadrature points of every cell: what makes a linear answer wrong at order theta^2.
    template <int dim>
    double largest_rotation(const LinearElasticProblem<dim> &problem)
    {
      using namespace dealii;
      FEValues<dim> fe_values(*problem.mapping, *problem.fe, *problem.quadrature, update_gradients);
      const FEValuesExtractors::Vector u(0);
      std::vector<Tensor<2, dim>>      grad(fe_values.n_quadrature_points);
      double                           largest = 0;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[u].get_function_gradients(problem.solution, grad);
            for (const auto &g : grad)
              {
                const Tensor<2, dim> w = 0.5 * (g - transpose(g));
                largest = std::max(largest, std::sqrt(0.5 * scalar_product(w, w)));
              }
          }
      return Utilities::MPI::max(largest, problem.communicator);
    }
  } // namespace

  template <int dim>
  bool LadderClimb<dim>::estimate_rung(const LinearStaticModel<dim> &model, const CaseParameters &rung_parameters,
                                       Rung &rung, std::map<std::string, std::vector<double>> &history,
                                       const std::vector<double> &mesh_sizes)
  {
    bool met = true;
    // Targets may name derived quantities (Quantities/Derived) as well as computed ones.
    auto rung_quantities = model.quantities;
    try
      {
        add_derived_quantities(p.derived, rung_quantities, model.problem->expression_variables());
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    for (const auto &n : names)
      {
        const auto found = rung_quantities.find(n);
        if (found == rung_quantities.end())
          throw InputError(target.pair_of.empty() ?
                             "case file '" + p.case_file + "', Target/Quantities: '" + n +
                               "' is not a reported quantity" :
                             "case file '" + p.case_file + "': '" + n + "' is not a reported quantity, "
                               "but case file '" + target.pair_of + "' targets it and names this case in "
                               "Target/Paired model: both models must report it under that name");
        rung.values[n] = found->second;
        history[n].push_back(found->second);
        // Assumed order in h for a smooth quantity: degree + 1 (displacements at points).
        const double attainable = planner.degree_rungs() ? 0 : attainable_order(rung.degree);
        const auto   e = estimate_discretization_error(history[n], mesh_sizes, rung.degree + 1.0, attainable);
        rung.estimates[n]      = e;
        rung.stop_estimates[n] = stop_rule.stop_estimate(n, e, target.adaptive || planner.degree_rungs());
      }
    if (p.error_estimates)
      {
        // The dual-weighted estimate stands in where the sequence cannot vouch for Richardson's.
        const auto dual = estimate_quantity_errors<dim>(context, rung_parameters, rung_quantities,
                                                        model.problem->triangulation.all_reference_cells_are_hyper_cube(),
                                                        {}, model.problem.get());
        for (const auto &n : names)
          if (const auto found = dual.relative.find(n); found != dual.relative.end())
            {
              rung.dual_estimates[n] = found->second;
              if (rung.stop_estimates[n] < 0)
                rung.stop_estimates[n] = found->second;
            }
      }
    for (const auto &n : names)
      met = met && rung.stop_estimates[n] >= 0 && rung.stop_estimates[n] <= target.relative_error;
    return met;
  }

  template <int dim>
  std::vector<bool> LadderClimb<dim>::refine_flags(const LinearStaticModel<dim> &model)
  {
    if (!target.goal_oriented)
      return kelly_refine_flags<dim>(*model.problem, model.problem->solution, target.refined_fraction);
    auto values = model.quantities;
    add_derived_quantities(p.derived, values, model.problem->expression_variables());
    std::string how;
    auto        flags = goal_oriented_refine_flags(*model.problem, names, values, p.derived, target.refined_fraction, how);
    if (root)
      std::cout << "  (d) refine for " << how << std::endl;
    return flags;
  }

  template <int dim>
  std::string LadderClimb<dim>::check_plane_stress(const LinearStaticModel<dim> &model, const Rung &rung,
                                                   const unsigned int k)
  {
    // (b) on every rung of a plane-stress model: its out-of-plane bound against the 3D solid.
    std::string needs_3d;
    if constexpr (dim == 2)
      {
        if (p.model == Model::plane_stress && !model.problem->mixed)
          {
            const auto   bound  = plane_stress_out_of_plane_bound(*model.problem);
            const double energy = model.quantities.at("strain_energy");
            out_of_plane = energy > 0 ? bound.energy_difference / energy : std::numeric_limits<double>::infinity();
            const auto verdict = out_of_plane_verdict(out_of_plane, model.problem->thickness,
                                                      target.relative_error, stand_in, k);
            dimension_reason = verdict.reason;
            needs_3d         = verdict.needs_3d;
            if ((k == 0 || stand_in) && root)
              std::cout << "  (b) " << dimension_reason << "\n";
            if (verdict.bound_shares_target) // the bound takes its share: estimate + bound must meet it
              for (const auto &n : names)
                met = met && rung.stop_estimates.at(n) + out_of_plane <= target.relative_error;
          }
        else if (stand_in)
          needs_3d = dimension_reason = "no out-of-plane bound for the mixed formulation";
      }
    return needs_3d;
  }

  template <int dim>
  std::optional<int> LadderClimb<dim>::climb_linear()
  {
    // Kelly's refine flags are computed over the whole mesh: adaptive rungs share it.
    if (target.adaptive && p.mesh_partition == PartitionRequest::distributed)
      throw InputError("case file '" + p.case_file + "': Discretization/Mesh partition = "
                       "distributed is not possible with Target/Refinement = adaptive (the "
                       "refine flags cover the whole mesh); use shared or auto");
    std::map<std::string, std::vector<double>> history;
    std::vector<double>                        mesh_sizes;
    for (unsigned int k = 0; k <= target.max_refinements && !met; ++k)
      {
        auto           rung_parameters = std::make_unique<CaseParameters>(p);
        const RungPlan plan            = planner.plan(k);
        // A follower pressure loads the finite-strain rungs; its small-deformation limit, the same
        // pressure on the undeformed boundary, loads the linear ones (else they would see no load
        // and find the rotations small).
        bool substituted          = false;
        rung_parameters->pressure = linear_pressure(p, context.prm, substituted);
        if (substituted && root && k == 0)
          std::cout << "  linear rungs: Finite strain/Follower pressure on the undeformed boundary ("
                    << rung_parameters->pressure << "), its small-deformation limit" << std::endl;
        rung_parameters->element_degree = plan.degree;
        if (target.adaptive)
          {
            rung_parameters->mesh_partition       = PartitionRequest::shared;
            rung_parameters->adaptive_refinements = adaptive_refinements;
          }
        else
          rung_parameters->global_refinements = p.global_refinements + plan.h_steps;
        if (k > 0 && !target.adaptive)
          try
            {
              // The next rung (one more uniform refinement, or a higher degree, of the last
              // rung's mesh) must fit in memory.
              refuse_refinement_beyond_memory(last_cells, dim, plan.refines_cells ? 1 : 0, plan.degree,
                                              dealii::Utilities::MPI::n_mpi_processes(context.communicator));
            }
          catch (const ModelTooLarge &e)
            {
              too_large             = e.what();
              rungs.back().decision = "target NOT met: the next rung would not fit in memory";
              if (root)
                std::cout << "  (d) no rung " << k + 1 << ": " << too_large << std::endl;
              break;
            }
        dealii::Timer rung_timer;
        // Goal-oriented refinement solves a dual per target with the rung's own solver.
        const std::function<void(LinearElasticProblem<dim> &)> keep_solver = [&](LinearElasticProblem<dim> &problem) {
          problem.keep_solver_for_duals = target.goal_oriented && target.adaptive;
        };
        auto model = solve_linear_static_model<dim>(context, *rung_parameters, false, keep_solver);
        last_cells          = model.problem->triangulation.n_global_active_cells();
        if (model.stopped_for_check)
          return 0;
        // Nothing to converge: every refinement would give the same zero (and adaptive indicators flag no cell).
        if (k == 0 && model.problem->solution.linfty_norm() == 0.)
          throw InputError("case file '" + p.case_file + "': the model carries no load (the displacement is zero "
                           "everywhere: no Loads, no prescribed Boundary conditions/Displacement or Rotation, "
                           "no follower pressure); a Target needs a loaded model");
        const bool hypercubes = model.problem->triangulation.all_reference_cells_are_hyper_cube();
        if (target.adaptive && !hypercubes)
          throw InputError("case file '" + p.case_file + "', Target/Refinement: adaptive refinement "
                           "needs a quadrilateral or hexahedral mesh (no hanging nodes on triangles or "
                           "tetrahedra); use uniform");
        if (k == 0 && !hypercubes)
          {
            planner.simplex_mesh(target.automatic);
            stop_rule.set_degree_rungs(planner.degree_rungs());
          }
        Rung rung;
        rung.degree          = rung_parameters->element_degree;
        rung.refinements     = rung_parameters->global_refinements;
        rung.adaptive_cycles = rung_parameters->adaptive_refinements.size();
        rung.dofs            = model.quantities.at("n_dofs");
        mesh_sizes.push_back(planner.mesh_size(target.adaptive, k, rung.dofs, dim));
        met = estimate_rung(model, *rung_parameters, rung, history, mesh_sizes);
        std::string needs_3d = check_plane_stress(model, rung, k); // why 2D cannot stand for the 3D part
        if (k == 0)
          {
            // (c) the geometric error of the linear answer, of order theta^2.
            const auto geometric = geometric_verdict(largest_rotation(*model.problem), target.relative_error,
                                                     target.allow_finite_strain);
            geometric_reason = geometric.reason;
            finite_strain    = geometric.finite_strain;
            if (root)
              std::cout << "  (c) " << geometric_reason << "\n";
            if (finite_strain && stand_in && needs_3d.empty())
              {
                // The out-of-plane bound is one of linear elasticity.
                needs_3d = dimension_reason = "finite strain needed, and the out-of-plane bound that "
                                              "justifies 2D holds for linear models only";
                finite_strain = false;
              }
          }
        if (!needs_3d.empty())
          {
            met           = false;
            rung.decision = "the plane-stress model cannot stand for the 3D part (" + needs_3d + ")";
            rung.seconds  = rung_timer.wall_time();
            print(rung);
            rungs.push_back(rung);
            return give_way_to_3d();
          }
        if (finite_strain)
          {
            // The linear answer is off by its geometric error whatever the mesh: climb in
            // finite strain instead, from the case's own mesh.
            met           = false;
            rung.decision = "finite strain needed: the climb goes on in finite strain";
          }
        else if (met)
          rung.decision = "estimate meets the target: stop";
        else if (k == target.max_refinements)
          rung.decision = "target NOT met within Target/Maximum refinements";
        else
          {
            rung.decision = planner.next_step(target.adaptive, k) +
                            stop_rule.why_go_on(rung.estimates, target.relative_error);
            if (target.adaptive)
              adaptive_refinements.push_back(refine_flags(model));
          }
        rung.seconds = rung_timer.wall_time();
        print(rung);
        rungs.push_back(rung);
        chosen_parameters = std::move(rung_parameters);
        chosen            = std::move(model);
        if (finite_strain)
          break;
      }
    return std::nullopt;
  }

  template <int dim>
  void LadderClimb<dim>::add_estimates_to_summary(RunSummary &summary, const Rung &rung) const
  {
    for (const auto &[n, e] : rung.estimates)
      if (e.available)
        {
          // What the stop rule read: the Richardson estimate, or its safety multiple while the
          // observed order is not steady (then the bare estimate is kept beside it).
          const double bound                        = rung.stop_or_bare_estimate(n);
          summary.quantities[n + "_error_estimate"] = bound;
          summary.quantities[n + "_observed_order"] = e.observed_order;
          // A plane-stress model standing for its 3D part: the error against the part.
          if (stand_in && out_of_plane >= 0)
            summary.quantities[n + "_error_estimate_against_3d"] = bound + out_of_plane;
          if (bound > e.relative)
            {
              summary.quantities[n + "_richardson_estimate"] = e.relative;
              summary.settings.insert({n + "_error_estimate_basis", "observed order not steady: " +
                                                                      stop_rule.safety_factor_text() +
                                                                      " x the Richardson estimate"});
            }
        }
      else if (const auto dual = rung.dual_estimates.find(n); dual != rung.dual_estimates.end())
        {
          summary.quantities[n + "_error_estimate"] = dual->second;
          summary.settings.insert({n + "_error_estimate_basis", "dual-weighted residual (Richardson: " + e.note + ")"});
        }
      else
        summary.settings.insert({n + "_error_estimate", e.note});
    for (const auto &[n, d] : rung.dual_estimates)
      summary.quantities[n + "_dual_error_estimate"] = d;
  }

  template <int dim>
  int LadderClimb<dim>::finish_linear()
  {
    // The chosen model's run: linear output as usual.
    const RunContext chosen_context{*chosen_parameters, context.prm, context.geometry, context.check_only,
                                    context.communicator};
    const auto &problem = *chosen.problem;
    RunSummary  summary = start_summary(chosen_context, problem.triangulation.all_reference_cells_are_hyper_cube());
    summary.settings.insert({"solver", to_string(problem.solver_method)});
    summary.settings.insert({"ladder", met                ? "target met" :
                                       too_large.empty() ? "target not met" :
                                                           "target not met: " + too_large});
    summary.settings.insert({"ladder_geometric_check", geometric_reason});
    summary.quantities = chosen.quantities;
    if (out_of_plane >= 0)
      {
        summary.settings.insert({"ladder_dimension_check", dimension_reason});
        summary.quantities["out_of_plane_bound"] = out_of_plane;
      }
    summary.quantities["ladder_rungs"]          = rungs.size() + earlier_rows.size();
    summary.quantities["ladder_total_seconds"]  = total.wall_time() + target.earlier_seconds;
    summary.quantities["target_relative_error"] = target.relative_error;
    add_estimates_to_summary(summary, rungs.back());
    finish_run(chosen_context, summary, problem.expression_variables(),
               [&](const std::string &directory) { write_fields(problem, directory); },
               [&](const RunSummary &finished) { return static_pictures(problem, finished); });
    if (root)
      write_ladder_csv(chosen_parameters->output_directory, names, all_rows());
    return met ? 0 : 4;
  }

  template bool LadderClimb<2>::estimate_rung(const LinearStaticModel<2> &, const CaseParameters &, Rung &,
                                              std::map<std::string, std::vector<double>> &, const std::vector<double> &);
  template bool LadderClimb<3>::estimate_rung(const LinearStaticModel<3> &, const CaseParameters &, Rung &,
                                              std::map<std::string, std::vector<double>> &, const std::vector<double> &);
  template std::vector<bool> LadderClimb<2>::refine_flags(const LinearStaticModel<2> &);
  template std::vector<bool> LadderClimb<3>::refine_flags(const LinearStaticModel<3> &);
  template std::string LadderClimb<2>::check_plane_stress(const LinearStaticModel<2> &, const Rung &, unsigned int);
  template std::string LadderClimb<3>::check_plane_stress(const LinearStaticModel<3> &, const Rung &, unsigned int);
  template std::optional<int> LadderClimb<2>::climb_linear();
  template std::optional<int> LadderClimb<3>::climb_linear();
  template void LadderClimb<2>::add_estimates_to_summary(RunSummary &, const Rung &) const;
  template void LadderClimb<3>::add_estimates_to_summary(RunSummary &, const Rung &) const;
  template int LadderClimb<2>::finish_linear();
  template int LadderClimb<3>::finish_linear();
} // namespace compliant
