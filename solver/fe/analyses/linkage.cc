#include "analyses/linkage.h"

#include <deal.II/base/timer.h>

#include "constraints/extra_constraints.h"
#include "constraints/rigid_motion_check.h"
#include "elasticity/global_constraints.h"
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
      if (p.formulation == Formulation::mixed)
        throw InputError("case file '" + p.case_file + "': Discretization/Formulation = mixed is for "
                         "linear static and modal analyses; the linkage analysis uses displacement elements");
      LinearElasticProblem<dim>         problem(p, context.geometry, comm,
                                                choose_mesh_partition(context, p, "the linkage analysis (pins tie DoFs of any two bodies)"));
      dealii::AffineConstraints<double> constraints;
      try
        {
          parse_checks(p.checks);
          problem.setup();
          validate_quantity_requests(problem);
          constraints = gather_constraints(problem, false);
          add_extra_constraints(problem, read_extra_constraints(context.prm), constraints);
          require_rigid_motion_held(problem, constraints, "the linkage's static solve");
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + p.case_file + "': " + e.what());
        }
      if (report_mesh_and_stop_if_check(context, problem.triangulation.n_global_active_cells(),
                                        problem.dof_handler.n_dofs(), ""))
        return 0;

      install_constraints(problem, std::move(constraints));
      problem.assemble();
      problem.solve();
      if (root)
        std::cout << "Solved: " << problem.statistics.iterations << " iterations ("
                  << to_string(p.solver_method) << "), assembly " << problem.statistics.assembly_seconds
                  << " s, solve " << problem.statistics.solve_seconds << " s" << std::endl;

      RunSummary summary =
        start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"solver", to_string(p.solver_method)});
      summary.settings.insert({"joints", "frictionless pins (radial ties)"});
      summary.quantities = compute_quantities(problem);
      summary.quantities["time_setup"]    = problem.statistics.setup_seconds;
      summary.quantities["time_assembly"] = problem.statistics.assembly_seconds;
      summary.quantities["time_solve"]    = problem.statistics.solve_seconds;
      summary.quantities["time_total"]    = timer.wall_time();

      auto variables   = problem.expression_variables();
      variables["rho"] = problem.materials.begin()->second.density; // as in 'modal'
      finish_run(context, summary, variables,
                 [&](const std::string &directory) { write_fields(problem, directory); });
      return 0;
    }
  } // namespace

  Analysis linkage_analysis()
  {
    return {{"linkage",
            "linear static analysis of links joined by frictionless pins (Extra constraints)",
            [](dealii::ParameterHandler &) {}}, // Extra constraints are declared by 'modal'
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
            }};
  }
} // namespace compliant
