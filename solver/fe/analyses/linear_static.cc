#include "analyses/linear_static.h"

#include "analyses/error_estimates.h"
#include "analyses/linear_static_model.h"
#include "quantities/comparison.h"
#include "output/field_output.h"
#include "output/run_pictures.h"

#include <iostream>

namespace compliant
{
  namespace
  {
    template <int dim>
    int run(const RunContext &context)
    {
      CaseParameters p           = context.parameters;
      bool           substituted = false;
      p.pressure                 = linear_pressure(context.parameters, context.prm, substituted);
      if (substituted && dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
        std::cout << "Loads: Finite strain/Follower pressure on the undeformed boundary (" << p.pressure
                  << "), its small-deformation limit in a linear analysis" << std::endl;
      auto model = solve_linear_static_model<dim>(context, p);
      if (model.stopped_for_check)
        return 0;
      const auto &problem = *model.problem;
      RunSummary  summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"solver", to_string(problem.solver_method)});
      summary.settings.insert({"solver_requested", to_string(p.solver_method)});
      summary.settings.insert({"mesh_partition", to_string(problem.mesh_partition.partition)});
      if (!problem.solver_note.empty())
        summary.settings.insert({"solver_note", problem.solver_note});
      if (!problem.statistics.multigrid_note.empty())
        summary.settings.insert({"multigrid", problem.statistics.multigrid_note});
      summary.quantities = model.quantities;
      if (p.error_estimates)
        {
          Quantities values = model.quantities; // derived ones too, for their estimates
          try
            {
              add_derived_quantities(p.derived, values, problem.expression_variables());
            }
          catch (const std::invalid_argument &e)
            {
              throw InputError("case file '" + p.case_file + "', Quantities/Derived: " + e.what());
            }
          const auto estimates = estimate_quantity_errors<dim>(
            context, p, values, problem.triangulation.all_reference_cells_are_hyper_cube(), {}, &problem);
          add_error_estimates(summary, estimates);
          if (estimates.available && dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
            std::cout << "Error estimates: " << estimates.absolute.size() << " quantities, enriched model "
                      << estimates.dual_dofs << " DoFs in " << estimates.dual_seconds << " s, its solve "
                      << estimates.dual_solve_seconds << " s in " << estimates.dual_iterations
                      << " iterations (the model itself " << model.seconds << " s, its solve "
                      << problem.statistics.solve_seconds << " s in " << problem.statistics.iterations
                      << " iterations)" << std::endl;
        }
      finish_run(context, summary, problem.expression_variables(),
                 [&](const std::string &directory) { write_fields(problem, directory); },
                 [&](const RunSummary &finished) { return static_pictures(problem, finished); });
      return 0;
    }
  } // namespace

  int run_linear_static(const RunContext &context)
  {
    return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
  }
} // namespace compliant
