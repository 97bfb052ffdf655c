#include "analyses/buckling.h"
#include "elasticity/global_constraints.h"
#include "analyses/buckling_parts.h"

#include <deal.II/base/timer.h>

#include "analyses/geometric_stiffness.h"
#include "analyses/linear_static_model.h"
#include "analyses/modal_eigensolver.h"
#include "analyses/modal_fields.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <numeric>

namespace compliant
{
  namespace
  {
    void declare(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Buckling");
      prm.declare_entry("Number of modes", "4", dealii::Patterns::Integer(1, 200),
                        "How many buckling factors (those nearest zero, either sign) and mode shapes.");
      prm.declare_entry("Tolerance", "1e-10", dealii::Patterns::Double(0, 1),
                        "Relative convergence tolerance of the eigenpairs (SLEPc).");
      prm.declare_entry("Maximum iterations", "1000", dealii::Patterns::Integer(1),
                        "Krylov-Schur restarts before giving up.");
      prm.declare_entry("Reference load factor", "0", dealii::Patterns::Double(0),
                        "0: buckling about the linear static state (the stress of the case's loads, "
                        "linear). > 0: about the finite-strain state at this load factor (the path "
                        "followed in load steps as in Analysis = nonlinear static, subsection Finite "
                        "strain): (K_T + mu dK_T/dlambda) phi = 0 with the tangent's change by a "
                        "step back from that state; the buckling factors are the reference plus mu. "
                        "Takes the deformation before buckling into account (shallow arches, "
                        "flexures under a rotation drive).");
      prm.leave_subsection();
    }

  } // namespace

  std::vector<dealii::PETScWrappers::MPI::Vector> add_buckling_factors(const EigenResult &result,
                                                                       const double       reference,
                                                                       Quantities        &q,
                                                                       const bool         root,
                                                                       const double       eigen_seconds)
  {
    // Nearest the reference state first, whatever the sign.
    std::vector<unsigned int> order(result.eigenvalues.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) {
      return std::abs(result.eigenvalues[a]) < std::abs(result.eigenvalues[b]);
    });
    double worst_error = 0;
    bool   negative    = false;
    std::vector<dealii::PETScWrappers::MPI::Vector> modes;
    for (unsigned int k = 0; k < order.size(); ++k)
      {
        const double factor = reference + result.eigenvalues[order[k]];
        q["buckling_factor_" + std::to_string(k + 1)] = factor;
        negative    = negative || factor < 0;
        worst_error = std::max(worst_error, result.backward_errors[order[k]]);
        modes.push_back(result.eigenvectors[order[k]]);
      }
    q["eigen_backward_error_max"] = worst_error;
    q["eigensolver_iterations"]   = result.iterations;
    q["time_eigensolve"]          = eigen_seconds;
    if (root)
      {
        std::cout << "Buckling: " << result.n_converged << " pairs converged, " << result.iterations << " restarts, "
                  << eigen_seconds << " s\n  mode  load factor\n";
        for (unsigned int k = 0; k < order.size(); ++k)
          std::cout << "  " << std::setw(4) << k + 1 << "  " << std::setprecision(10)
                    << q["buckling_factor_" + std::to_string(k + 1)] << "\n";
        if (negative)
          std::cout << "  A negative factor -f: the part buckles under the loads reversed and scaled by f "
                       "(a stress state with both tension and compression can buckle either way).\n";
        if (reference > 0 && std::any_of(result.eigenvalues.begin(), result.eigenvalues.end(), [](double e) { return e < 0; }))
          std::cout << "  A factor below the reference load factor " << reference
                    << " belongs to a mode that stiffens as the load grows: extrapolated back, not a critical "
                       "point ahead.\n";
        std::cout << std::flush;
      }
    return modes;
  }

  BucklingSettings read_buckling_settings(const dealii::ParameterHandler &prm)
  {
    return {static_cast<unsigned int>(prm.get_integer({"Buckling"}, "Number of modes")),
            prm.get_double({"Buckling"}, "Tolerance"),
            static_cast<unsigned int>(prm.get_integer({"Buckling"}, "Maximum iterations")),
            prm.get_double({"Buckling"}, "Reference load factor")};
  }

  template <int dim>
  LinearBuckling<dim> solve_linear_buckling(const RunContext &context, const BucklingSettings &settings)
  {
    const auto         &p = context.parameters;
    LinearBuckling<dim> buckling;
    // The reference state: the linear static solution under the case's loads, matrix kept.
    buckling.model = solve_linear_static_model<dim>(context, p, true);
    if (buckling.model.stopped_for_check)
      return buckling;
    auto &problem = *buckling.model.problem;
    if (settings.n_modes > problem.dof_handler.n_dofs() / 2)
      throw InputError("case file '" + p.case_file + "': Buckling/Number of modes = " +
                       std::to_string(settings.n_modes) + " is too many for " +
                       std::to_string(problem.dof_handler.n_dofs()) + " DoFs");

    dealii::Timer                            geometric_timer;
    dealii::PETScWrappers::MPI::SparseMatrix minus_geometric;
    assemble_geometric_stiffness(problem, minus_geometric);
    minus_geometric *= -1.; // K phi = lambda (-K_sigma) phi
    buckling.geometric_seconds = geometric_timer.wall_time();
    if (minus_geometric.frobenius_norm() == 0)
      throw InputError("case file '" + p.case_file + "': the loads and prescribed displacements leave the "
                       "part unstressed; buckling needs a stress state (Loads, Boundary conditions)");

    EigenSettings eigen;
    eigen.n_modes                = settings.n_modes;
    eigen.tolerance              = settings.tolerance;
    eigen.max_iterations         = settings.max_iterations;
    eigen.petsc_options          = p.petsc_options;
    eigen.shift                  = 0;
    eigen.definite_second_matrix = false;
    dealii::Timer eigen_timer;
    buckling.result        = solve_eigenproblem(problem.system_matrix, minus_geometric, problem.locally_owned_dofs, eigen);
    buckling.eigen_seconds = eigen_timer.wall_time();
    return buckling;
  }

  template <int dim>
  void distribute_support_constraints(const LinearElasticProblem<dim>                 &problem,
                                      std::vector<dealii::PETScWrappers::MPI::Vector> &modes)
  {
    if (problem.constraints_gathered)
      {
        // Extra constraints tie DoFs across ranks: their whole set, without prescribed values.
        auto homogeneous = gather_constraints(problem, true);
        homogeneous.close();
        for (auto &mode : modes)
          homogeneous.distribute(mode);
        return;
      }
    dealii::AffineConstraints<double> homogeneous;
    homogeneous.reinit(problem.locally_relevant_dofs);
    problem.add_support_constraints(problem.dof_handler, homogeneous, true);
    for (const auto &rigid : problem.rigid_boundaries)
      rigid.add_constraints(homogeneous); // a rigid piece moves rigidly in the mode too
    homogeneous.close();
    for (auto &mode : modes)
      homogeneous.distribute(mode);
  }

  namespace
  {
    template <int dim>
    int run(const RunContext &context)
    {
      const bool             root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
      dealii::Timer          timer;
      const BucklingSettings settings = read_buckling_settings(context.prm);
      if (settings.reference_load_factor > 0)
        return run_buckling_about_finite_strain_state<dim>(context, settings);

      if (context.parameters.rigid.find_first_not_of(" \t\r\n") != std::string::npos)
        throw InputError("case file '" + context.parameters.case_file + "', Boundary conditions/Rigid: linear "
                         "buckling leaves out the rigid pieces' geometric stiffness (the turn of the forces "
                         "they carry); buckle about a finite-strain state instead (Buckling/Reference load "
                         "factor > 0)");
      auto buckling = solve_linear_buckling<dim>(context, settings);
      if (buckling.model.stopped_for_check)
        return 0;
      auto &problem = *buckling.model.problem;

      RunSummary summary = start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
      summary.settings.insert({"eigensolver", "SLEPc Krylov-Schur, shift-and-invert about 0, MUMPS"});
      summary.settings.insert({"reference_state", "linear static under the case's loads (load factor 1)"});
      summary.settings.insert({"solver", to_string(problem.solver_method)});
      summary.quantities = buckling.model.quantities;
      auto modes = add_buckling_factors(buckling.result, 0, summary.quantities, root, buckling.eigen_seconds);
      summary.quantities["time_geometric_stiffness"] = buckling.geometric_seconds;
      summary.quantities["time_total"]               = timer.wall_time();
      distribute_support_constraints(problem, modes);
      finish_run(context, summary, problem.expression_variables(), [&](const std::string &directory) {
        write_mode_shapes(problem, modes, directory);
      });
      return 0;
    }
  } // namespace

  template LinearBuckling<2> solve_linear_buckling<2>(const RunContext &, const BucklingSettings &);
  template LinearBuckling<3> solve_linear_buckling<3>(const RunContext &, const BucklingSettings &);
  template void distribute_support_constraints<2>(const LinearElasticProblem<2> &,
                                                  std::vector<dealii::PETScWrappers::MPI::Vector> &);
  template void distribute_support_constraints<3>(const LinearElasticProblem<3> &,
                                                  std::vector<dealii::PETScWrappers::MPI::Vector> &);

  Analysis buckling_analysis()
  {
    return {{"buckling",
             "linearized buckling about the linear static state, (K + lambda K_sigma) phi = 0 (SLEPc "
             "shift-and-invert); the factors nearest zero and their mode shapes; settings in the "
             "Buckling subsection",
             declare},
            [](const RunContext &context) {
              return context.parameters.dimension == 2 ? run<2>(context) : run<3>(context);
            }};
  }
} // namespace compliant
