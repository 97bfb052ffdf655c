#include "analyses/linear_static.h"

#include "analyses/linear_static_model.h"
#include "ladder/model_ladder.h"
#include "ladder/paired_model.h"
#include "output/field_output.h"

namespace compliant
{
  namespace
  {
    template <int dim>
    int run(const RunContext &context)
    {
      const TargetSettings target =
        read_target_settings(const_cast<dealii::ParameterHandler &>(context.prm));
      if (target.relative_error > 0)
        return run_model_ladder<dim>(context, target);

      const auto &p     = context.parameters;
      if (!target.paired_model.empty())
        {
          // Only the ladder reads the pair; --check still validates it.
          if (context.check_only)
            read_paired_model(p, context.geometry, target.paired_model, context.communicator);
          if (dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
            std::cout << "Target/Paired model is read by the model ladder only (Target/Relative error "
                         "= 0 here): this run solves " << p.case_file << " as set\n";
        }
      auto        model = solve_linear_static_model<dim>(context, p);
      if (model.stopped_for_check)
        return 0;
      const auto &problem = *model.problem;
      RunSummary  summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"solver", problem.solver_method});
      summary.settings.insert({"solver_requested", p.solver_method});
      summary.settings.insert({"mesh_partition", to_string(problem.mesh_partition.partition)});
      if (!problem.solver_note.empty())
        summary.settings.insert({"solver_note", problem.solver_note});
      if (!problem.statistics.multigrid_note.empty())
        summary.settings.insert({"multigrid", problem.statistics.multigrid_note});
      summary.quantities = model.quantities;
      finish_run(context, summary, problem.expression_variables(),
                 [&](const std::string &directory) { write_fields(problem, directory); });
      return 0;
    }
  } // namespace

  Analysis linear_static_analysis()
  {
    return {"linear static",
            "small-strain linear elasticity, one solve; with Target/Relative error > 0 the model "
            "ladder chooses the discretization and, if needed, finite strain",
            [](dealii::ParameterHandler &prm) { declare_target_settings(prm); },
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
            }};
  }
} // namespace compliant
