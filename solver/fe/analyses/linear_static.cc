#include "analyses/linear_static.h"

#include <deal.II/base/timer.h>

#include "elasticity/linear_elastic_problem.h"
#include "output/field_output.h"
#include "quantities/quantities.h"

#include <iostream>

namespace compliant
{
  namespace
  {
    template <int dim>
    int run(const RunContext &context)
    {
      const auto   &p    = context.parameters;
      MPI_Comm      comm = context.communicator;
      const bool    root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
      dealii::Timer timer;
      LinearElasticProblem<dim> problem(p, context.geometry, comm);
      problem.matrix_free_allowed = true; // one solve of K u = f: no stored matrix needed
      try
        {
          parse_checks(p.checks);
          problem.setup();
          validate_quantity_requests(problem);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + p.case_file + "': " + e.what());
        }
      if (report_mesh_and_stop_if_check(context, problem.triangulation.n_active_cells(),
                                        problem.dof_handler.n_dofs(), ""))
        return 0;

      problem.assemble();
      problem.solve();
      if (root)
        {
          if (!problem.solver_note.empty())
            std::cout << "Linear solver: " << problem.solver_note << std::endl;
          std::cout << "Solved: " << problem.statistics.iterations << " iterations ("
                    << problem.solver_method << "), assembly " << problem.statistics.assembly_seconds
                    << " s, solve " << problem.statistics.solve_seconds << " s";
          if (!problem.statistics.level_dofs.empty())
            {
              std::cout << " (multigrid set-up " << problem.statistics.preconditioner_setup_seconds
                        << " s, " << problem.statistics.coarse_iterations
                        << " coarse CG iterations; DoFs per degree:";
              for (const auto n : problem.statistics.level_dofs)
                std::cout << ' ' << n;
              std::cout << ')';
            }
          std::cout << std::endl;
        }

      RunSummary summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"solver", problem.solver_method});
      summary.settings.insert({"solver_requested", p.solver_method});
      if (!problem.solver_note.empty())
        summary.settings.insert({"solver_note", problem.solver_note});
      summary.quantities = compute_quantities(problem);
      summary.quantities["solver_iterations"] = problem.statistics.iterations;
      summary.quantities["time_setup"]    = problem.statistics.setup_seconds;
      summary.quantities["time_assembly"] = problem.statistics.assembly_seconds;
      summary.quantities["time_solve"]    = problem.statistics.solve_seconds;
      if (!problem.statistics.level_dofs.empty())
        {
          summary.quantities["time_preconditioner_setup"] =
            problem.statistics.preconditioner_setup_seconds;
          summary.quantities["solver_coarse_iterations"] = problem.statistics.coarse_iterations;
        }
      summary.quantities["time_total"]    = timer.wall_time();

      finish_run(context, summary, problem.expression_variables(),
                 [&](const std::string &directory) { write_fields(problem, directory); });
      return 0;
    }
  } // namespace

  Analysis linear_static_analysis()
  {
    return {"linear static",
            "small-strain linear elasticity, one solve",
            [](dealii::ParameterHandler &) {},
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
            }};
  }
} // namespace compliant
