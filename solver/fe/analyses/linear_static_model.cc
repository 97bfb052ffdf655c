#include "analyses/linear_static_model.h"

#include "constraints/extra_constraints.h"
#include "constraints/rigid_motion_check.h"
#include "elasticity/global_constraints.h"

#include <deal.II/base/timer.h>

#include <iostream>

namespace compliant
{
  std::string linear_pressure(const CaseParameters &parameters, const dealii::ParameterHandler &prm,
                              bool &substituted)
  {
    const auto blank = [](const std::string &text) { return text.find_first_not_of(" \t") == std::string::npos; };
    std::string follower;
    try
      {
        follower = prm.get(std::vector<std::string>{"Finite strain"}, "Follower pressure");
      }
    catch (...) // not declared for this analysis
      {
      }
    substituted = blank(parameters.pressure) && !blank(follower);
    return substituted ? follower : parameters.pressure;
  }

  template <int dim>
  LinearStaticModel<dim> solve_linear_static_model(const RunContext &context, const CaseParameters &p,
                                                   const bool keep_matrix,
                                                   const std::function<void(LinearElasticProblem<dim> &)> &before_solve)
  {
    MPI_Comm               comm = context.communicator;
    const bool             root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    dealii::Timer          timer;
    LinearStaticModel<dim> model;
    dealii::AffineConstraints<double> extended; // the supports' constraints and the extra ones
    // Pins, mirror ties and edge supports tie DoFs of any two places: gathered on every rank.
    const ExtraConstraints extra = read_extra_constraints(context.prm);
    // Refine flags from the model ladder's adaptive rungs are over the whole mesh.
    const auto partition = choose_mesh_partition(
      context, p, !extra.empty()                  ? "Extra constraints (gathered on every rank)" :
                  !p.adaptive_refinements.empty() ? "adaptive refinement (Target/Refinement)" :
                                                    "");
    model.problem = std::make_unique<LinearElasticProblem<dim>>(p, context.geometry, comm, partition);
    auto &problem      = *model.problem;
    problem.matrix_free_allowed = !keep_matrix; // one solve of K u = f: no stored matrix needed
    try
      {
        parse_checks(p.checks);
        problem.setup();
        validate_quantity_requests(problem);
        if (!extra.empty())
          {
            extended = gather_constraints(problem, false);
            add_extra_constraints(problem, extra, extended);
          }
        require_rigid_motion_held(problem, extra.empty() ? problem.constraints : extended, "a linear static solve");
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    // The log names this model's degree (a ladder rung's, not the case file's).
    const RunContext model_context{p, context.prm, context.geometry, context.check_only, context.communicator};
    if (report_mesh_and_stop_if_check(model_context, problem.triangulation.n_global_active_cells(),
                                      problem.dof_handler.n_dofs(),
                                      partition.partition == MeshPartition::distributed ?
                                        ", mesh distributed" : ""))
      {
        model.stopped_for_check = true;
        return model;
      }

    if (!extra.empty())
      install_constraints(problem, std::move(extended));
    try
      {
        problem.assemble(); // load expressions are evaluated here
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    if (before_solve)
      before_solve(problem);
    problem.solve();
    if (root)
      {
        if (!problem.solver_note.empty())
          std::cout << "Linear solver: " << problem.solver_note << std::endl;
        std::cout << "Solved: " << problem.statistics.iterations << " iterations ("
                  << to_string(problem.solver_method) << "), assembly " << problem.statistics.assembly_seconds
                  << " s, solve " << problem.statistics.solve_seconds << " s";
        if (!problem.statistics.level_dofs.empty())
          {
            std::cout << " (multigrid set-up " << problem.statistics.preconditioner_setup_seconds
                      << " s, " << problem.statistics.coarse_iterations
                      << " coarse CG iterations; DoFs per degree:";
            for (const auto n : problem.statistics.level_dofs)
              std::cout << ' ' << n;
            std::cout << "; " << problem.statistics.multigrid_note << ')';
          }
        std::cout << std::endl;
      }
    model.quantities                       = compute_quantities(problem);
    model.quantities["solver_iterations"]  = problem.statistics.iterations;
    model.quantities["time_setup"]         = problem.statistics.setup_seconds;
    model.quantities["time_assembly"]      = problem.statistics.assembly_seconds;
    model.quantities["time_solve"]         = problem.statistics.solve_seconds;
    if (!problem.statistics.level_dofs.empty())
      {
        model.quantities["time_preconditioner_setup"] = problem.statistics.preconditioner_setup_seconds;
        model.quantities["solver_coarse_iterations"]  = problem.statistics.coarse_iterations;
      }
    model.seconds                    = timer.wall_time();
    model.quantities["time_total"]   = model.seconds;
    return model;
  }

  template LinearStaticModel<2> solve_linear_static_model<2>(
    const RunContext &, const CaseParameters &, bool, const std::function<void(LinearElasticProblem<2> &)> &);
  template LinearStaticModel<3> solve_linear_static_model<3>(
    const RunContext &, const CaseParameters &, bool, const std::function<void(LinearElasticProblem<3> &)> &);
} // namespace compliant
