// Buckling about a converged finite-strain state: the path is followed in load steps to the
// reference load factor lambda_0, the tangent there and at lambda_0 - delta give its rate of change,
// and (K_T + mu dK_T/dlambda) phi = 0 extrapolates linearly to where it turns singular,
// lambda = lambda_0 + mu. Near the critical point the extrapolation becomes exact; far below it, it
// still includes what linear buckling leaves out: the deformation and stiffening or softening
// before buckling.
#include <deal.II/base/timer.h>

#include "analyses/buckling_parts.h"
#include "analyses/modal_fields.h"
#include "analyses/nonlinear_static.h"
#include "finite_strain/finite_strain_load_path.h"
#include "quantities/comparison.h"

#include <iostream>

namespace compliant
{
  template <int dim>
  int run_buckling_about_finite_strain_state(const RunContext &context, const BucklingSettings &settings)
  {
    const auto &p    = context.parameters;
    MPI_Comm    comm = context.communicator;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    const double lambda0 = settings.reference_load_factor;
    PathSettings path    = read_path_settings(const_cast<dealii::ParameterHandler &>(context.prm), p, dim);
    // The eigenproblem about the state is set up on the local constraints alone: never drop them.
    if (!path.finite_strain.extra.empty())
      throw InputError("case file '" + p.case_file + "', Extra constraints: pins, mirror ties and edge supports "
                       "are held by linear buckling and by nonlinear static, not by buckling about a "
                       "finite-strain state (Buckling/Reference load factor > 0)");
    if (!path.finite_strain.follower_pressure.empty())
      throw InputError("case file '" + p.case_file + "': Buckling/Reference load factor > 0 needs a symmetric "
                       "tangent; Finite strain/Follower pressure makes it unsymmetric");
    dealii::Timer            timer;
    FiniteStrainProblem<dim> problem(p, path.finite_strain, context.geometry, comm);
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
    if (report_mesh_and_stop_if_check(context, problem.triangulation.n_global_active_cells(),
                                      problem.dof_handler.n_dofs(), ", finite-strain reference state"))
      return 0;
    if (settings.n_modes > problem.dof_handler.n_dofs() / 2)
      throw InputError("case file '" + p.case_file + "': Buckling/Number of modes = " +
                       std::to_string(settings.n_modes) + " is too many for " +
                       std::to_string(problem.dof_handler.n_dofs()) + " DoFs");

    // The reference state: the stability check stays on, so a path that turns unstable first stops.
    FiniteStrainLoadPath<dim> to_reference(problem, {}, lambda0);
    const LoadPathResult      reached = follow_load_path(to_reference, path.stepping, [](const AcceptedStep &) {});
    if (!reached.failure.empty())
      {
        if (root)
          std::cerr << "error: the path to Buckling/Reference load factor = " << lambda0
                    << " did not get there: " << reached.failure << std::endl;
        return 3;
      }
    const Quantities reference_quantities = compute_quantities(problem);

    // The tangent there and a step back; their difference per load factor.
    dealii::AffineConstraints<double>        homogeneous;
    dealii::PETScWrappers::MPI::SparseMatrix tangent, change;
    const auto                              &assembled = problem.assemble_tangent(homogeneous);
    tangent.reinit(assembled);
    tangent.copy_from(assembled);
    const auto   state = problem.solution;
    const double delta = 1e-3 * lambda0;
    try
      {
        problem.solve_to(lambda0 - delta);
      }
    catch (const StepFailure &e)
      {
        if (root)
          std::cerr << "error: the step back from the reference state failed: " << e.what() << std::endl;
        return 3;
      }
    dealii::AffineConstraints<double> unused;
    const auto                       &before = problem.assemble_tangent(unused);
    change.reinit(tangent);
    change.copy_from(before);
    change.add(-1., tangent); // K(lambda0 - delta) - K(lambda0) = -delta dK/dlambda
    change *= 1. / delta;     // -dK/dlambda: K_T phi = mu (-dK/dlambda) phi
    // Constrained rows go to infinite eigenvalues: no diagonal in the second matrix.
    for (const auto i : problem.locally_owned_dofs)
      if (homogeneous.is_constrained(i))
        change.set(i, i, 0.);
    change.compress(dealii::VectorOperation::insert);
    problem.restore(state, lambda0);

    EigenSettings eigen;
    eigen.n_modes                = settings.n_modes;
    eigen.tolerance              = settings.tolerance;
    eigen.max_iterations         = settings.max_iterations;
    eigen.petsc_options          = p.petsc_options;
    eigen.definite_second_matrix = false;
    eigen.symmetric              = dim == 2 || problem.rigid_boundaries.empty(); // 3D rigid: unsymmetric
    dealii::Timer eigen_timer;
    EigenResult   result = solve_eigenproblem(tangent, change, problem.locally_owned_dofs, eigen);

    RunSummary summary = start_summary(context, problem.triangulation.all_reference_cells_are_hyper_cube());
    summary.settings.insert({"eigensolver", "SLEPc Krylov-Schur, shift-and-invert about 0, MUMPS"});
    summary.settings.insert({"reference_state", "finite strain at load factor " + std::to_string(lambda0)});
    summary.quantities = reference_quantities;
    auto modes = add_buckling_factors(result, lambda0, summary.quantities, root, eigen_timer.wall_time());
    summary.quantities["reference_load_factor"] = lambda0;
    summary.quantities["load_steps"]            = reached.steps;
    summary.quantities["time_total"]            = timer.wall_time();
    for (auto &mode : modes)
      homogeneous.distribute(mode);
    finish_run(context, summary, problem.expression_variables(),
               [&](const std::string &directory) { write_mode_shapes(problem, modes, directory); });
    return 0;
  }

  template int run_buckling_about_finite_strain_state<2>(const RunContext &, const BucklingSettings &);
  template int run_buckling_about_finite_strain_state<3>(const RunContext &, const BucklingSettings &);
} // namespace compliant
