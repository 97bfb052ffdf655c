// Quantities/Error estimates at finite strain. The enriched model (degree p + 1 on the same mesh,
// or the once-refined mesh past the element's highest degree) is solved to the run's end state
// and J(u+) - J(u_p) is each quantity's estimate: to leading order the DWR estimate with the dual
// of the tangent at the converged state on the enriched space. The enriched state is found by
// Newton at the end load from the run's state carried up (a hyperelastic body's state depends on
// the load, not on the path to it), a few Newton iterations where following the path again costs
// every step's. A path with limit points or bifurcations is followed again instead (their load
// factors have estimates only from a path of their own), as is one that stopped short. The enriched run writes to a scratch
// directory inside the output directory, removed after.
#include "analyses/error_estimates.h"
#include "analyses/nonlinear_static.h"

#include <deal.II/base/utilities.h>

#include "output/summary.h"

#include <filesystem>
#include <sstream>

namespace compliant
{
  template <int dim>
  int run_nonlinear_static_with_estimates(const RunContext &context)
  {
    const auto &p = context.parameters;
    if (!p.error_estimates || context.check_only)
      return run_nonlinear_static<dim>(context);
    const auto amend = [&](RunSummary &summary, const FiniteStrainProblem<dim> &model) {
      const bool critical_points =
        summary.quantities.count("limit_points") != 0 || summary.quantities.count("bifurcations") != 0;
      // A path that stopped short (unstable, a failed step, a signal) is followed again too, and
      // then ends elsewhere: no estimate of a state Newton would find whether stable or not.
      const bool completed = summary.settings.count("status") != 0 && summary.settings.at("status") == "completed";
      // Friction makes the state depend on the path to it: the enriched model follows it too.
      const bool friction     = model.contact && model.contact->has_friction();
      const bool follow_again = critical_points || !completed || friction;
      std::string how_solved;
      double      enriched_solve_seconds = 0;
      unsigned    enriched_newton        = 0;
      auto estimates = estimate_quantity_errors<dim>(
        context, p, summary.quantities,
        summary.settings.count("cell_type") == 0 || summary.settings.at("cell_type") == "hypercube",
        [&](const RunContext &enriched_context, const CaseParameters &enriched) {
          CaseParameters scratch   = enriched;
          scratch.output_directory = p.output_directory + "/.error_estimate";
          scratch.write_fields     = false;
          scratch.write_pictures   = false;
          if (scratch.element_degree > p.element_degree) // the same mesh: cut it the same way
            scratch.mesh_partition = partition_of_model(model.mesh_partition.partition);
          const RunContext scratch_context{scratch, enriched_context.prm, enriched_context.geometry, false,
                                           enriched_context.communicator};
          Quantities       plus;
          std::size_t      dofs = 0;
          bool             from_state = false;
          const int        rc   = run_nonlinear_static<dim>(
            scratch_context,
            [&](RunSummary &enriched_summary, const FiniteStrainProblem<dim> &) {
              plus       = enriched_summary.quantities;
              from_state = enriched_summary.settings.count("path") != 0;
              dofs = static_cast<std::size_t>(enriched_summary.quantities.at("n_dofs"));
            },
            follow_again ? nullptr : &model);
          if (dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0)
            std::filesystem::remove_all(scratch.output_directory);
          // A path that stopped short ends elsewhere: nothing to compare.
          if (rc != 0 || plus.count("load_factor") == 0 || summary.quantities.count("load_factor") == 0 ||
              plus.at("load_factor") != summary.quantities.at("load_factor"))
            {
              plus.clear();
              return std::make_pair(plus, dofs);
            }
          enriched_newton        = static_cast<unsigned>(plus.at("newton_iterations"));
          enriched_solve_seconds = plus.count("time_linear_solves") ? plus.at("time_linear_solves") : 0;
          std::ostringstream how;
          if (from_state)
            how << ", its state by Newton at the end load from the model's state carried up (" << enriched_newton
                << " iterations)";
          else
            how << ", its state by following the path again (" << plus.at("load_steps") << " steps, "
                << enriched_newton << " Newton iterations"
                << (critical_points ? ": the path's limit points and bifurcations need a path of their own)" :
                                      ")");
          how_solved = how.str();
          return std::make_pair(plus, dofs);
        });
      if (estimates.available)
        {
          estimates.how += how_solved;
          estimates.dual_iterations    = enriched_newton;
          estimates.dual_solve_seconds = enriched_solve_seconds;
        }
      add_error_estimates(summary, estimates);
    };
    return run_nonlinear_static<dim>(context, amend);
  }

  template int run_nonlinear_static_with_estimates<2>(const RunContext &);
  template int run_nonlinear_static_with_estimates<3>(const RunContext &);
} // namespace compliant
