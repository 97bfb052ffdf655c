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
        std::cout << "Solved: " << problem.statistics.iterations << " iterations ("
                  << p.solver_method << "), assembly " << problem.statistics.assembly_seconds
                  << " s, solve " << problem.statistics.solve_seconds << " s" << std::endl;

      RunSummary summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"solver", p.solver_method});
      summary.quantities = compute_quantities(problem);
      summary.quantities["solver_iterations"] = problem.statistics.iterations;
      summary.quantities["time_setup"]    = problem.statistics.setup_seconds;
      summary.quantities["time_assembly"] = problem.statistics.assembly_seconds;
      summary.quantities["time_solve"]    = problem.statistics.solve_seconds;
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
