// The linear elastic problem's solver: which method a case gets (matrix-free p-multigrid, CG +
// GAMG or MUMPS) and why, and the solve with its fall-backs under 'auto'.
#include "elasticity/linear_elastic_problem.h"

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_control.h>

#include "fast_solver/coarse_level_solver.h"
#include "fast_solver/elasticity_operator.h"
#include "fast_solver/p_multigrid_solver.h"
#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_linear_solver.h"
#include "linear_algebra/rigid_body_modes.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  void LinearElasticProblem<dim>::choose_solver_method()
  {
    const SolverMethod requested = parameters.solver_method;
    const bool hexahedra = triangulation.all_reference_cells_are_hyper_cube();
    const bool matrix_free_possible = hexahedra && matrix_free_allowed && rigid_boundaries.empty();
    std::string why_not;
    if (!hexahedra)
      why_not = "the matrix-free operator needs quadrilateral/hexahedral cells";
    else if (!rigid_boundaries.empty())
      why_not = "a rigid boundary ties its nodes together (the multigrid levels cannot)";
    else if (!matrix_free_allowed)
      why_not = "this analysis needs the assembled stiffness matrix";
    solver_note.clear();
    if (mixed)
      {
        // The u-p system is a symmetric saddle point: neither the matrix-free elasticity operator
        // nor CG applies.
        solver_method = SolverMethod::direct;
        if (requested != SolverMethod::direct && requested != SolverMethod::automatic)
          solver_note = to_string(requested) + " requested, but the mixed u-p system is indefinite: using MUMPS (direct)";
        else if (requested == SolverMethod::automatic)
          solver_note = "auto: MUMPS for the mixed u-p (saddle-point) system";
        return;
      }
    if (requested == SolverMethod::matrix_free)
      {
        solver_method = matrix_free_possible ? SolverMethod::matrix_free : SolverMethod::cg_amg;
        if (!matrix_free_possible)
          solver_note = "matrix-free requested, but " + why_not + ": using cg-amg";
      }
    else if (requested == SolverMethod::automatic)
      {
        // Measured (cases/benchmarks): p-multigrid is fastest for degree >= 2 on hexahedra; below
        // ~3e4 DoFs MUMPS costs less than any set-up; otherwise AMG on the assembled matrix.
        if (matrix_free_possible && parameters.element_degree >= 2)
          solver_method = SolverMethod::matrix_free,
          solver_note   = "auto: matrix-free p-multigrid (degree " +
                        std::to_string(parameters.element_degree) + " to 1, AMG on degree 1)";
        else if (dof_handler.n_dofs() < 30000)
          solver_method = SolverMethod::direct, solver_note = "auto: MUMPS for a small system";
        else
          solver_method = SolverMethod::cg_amg,
          solver_note   = "auto: CG + GAMG on the assembled matrix" +
                        (why_not.empty() ? std::string(" (degree 1)") : " (" + why_not + ")");
      }
    else
      solver_method = requested;
  }

  template <int dim>
  void LinearElasticProblem<dim>::require_assembled_matrix(const std::string &reason)
  {
    if (solver_method != SolverMethod::matrix_free)
      return;
    // The rule of 'auto' without the matrix-free operator: MUMPS below 30k DoFs (a mirror-tied plate
    // of 9.8k DoFs took 270 CG + GAMG iterations, 3.8 s), CG + GAMG above.
    const bool small = parameters.solver_method == SolverMethod::automatic && dof_handler.n_dofs() < 30000;
    solver_method    = small ? SolverMethod::direct : SolverMethod::cg_amg;
    solver_note      = "matrix-free not possible with " + reason + ": using " + to_string(solver_method);
  }

  template <int dim>
  void LinearElasticProblem<dim>::solve()
  {
    Timer                      timer;
    double                     kept_seconds = 0; // keeping the degree-1 level for the estimates
    PETScWrappers::MPI::Vector x(locally_owned_dofs, communicator);
    const bool                 solved = solve_from_coarse_twin(x);
    if (!solved && solver_method == SolverMethod::matrix_free && !solve_matrix_free(x))
      {
        // 'auto' only: the iterative method struggled (very thin cells); MUMPS is exact.
        solver_method = SolverMethod::direct;
        allocate_matrix();
        assemble();
      }
    if (!solved && solver_method != SolverMethod::matrix_free)
      {
        const bool iterative = solver_method != SolverMethod::direct;
        const auto modes     = iterative ? rigid_body_modes(*mapping, dof_handler, communicator) :
                                           std::vector<PETScWrappers::MPI::Vector>();
        LinearSolverSettings settings{solver_method, parameters.solver_tolerance,
                                      parameters.solver_max_iterations, parameters.petsc_options};
        if (parameters.solver_method == SolverMethod::automatic && iterative)
          settings.max_iterations = std::min(settings.max_iterations, 300u);
        // With error estimates, a degree-1 model's GAMG on hexahedra is kept: the enriched
        // (degree-2) model's multigrid takes it as its degree-1 level instead of building its own.
        const bool keep = parameters.error_estimates && fe->degree == 1 &&
                          triangulation.all_reference_cells_are_hyper_cube();
        PC         kept = nullptr;
        try
          {
            if (solver_method == SolverMethod::direct)
              statistics.iterations = solve_direct(x);
            else
              statistics.iterations = solve_linear_system(system_matrix, x, system_rhs, modes, settings, dim,
                                                          keep ? &kept : nullptr);
          }
        catch (const std::runtime_error &e)
          {
            if (parameters.solver_method != SolverMethod::automatic || !iterative)
              throw;
            solver_note += "; CG + GAMG did not converge in " +
                           std::to_string(settings.max_iterations) +
                           " iterations: solved again with MUMPS (direct)";
            solver_method         = SolverMethod::direct;
            statistics.iterations = solve_direct(x);
          }
        // Outside the try (its errors are not CG's) and the solve's time (it serves the estimates).
        if (kept)
          {
            Timer keeping;
            degree_one_level = fast_solver::degree_one_level_from_preconditioner<dim>(
              dof_handler, homogeneous_constraints(), kept,
              fast_solver::PMultigridSettings().warm_start_coarse_tolerance, communicator);
            kept_seconds = keeping.wall_time();
          }
      }
    constraints.distribute(x);
    solution = x;
    statistics.solve_seconds = timer.wall_time() - kept_seconds;
  }

  template <int dim>
  unsigned int LinearElasticProblem<dim>::solve_direct(PETScWrappers::MPI::Vector &x)
  {
    if (!factorization)
      {
        insert_petsc_options(parameters.petsc_options);
        // The stiffness is symmetric (constraints condensed symmetrically): LDL^T, 0.72 of LU's
        // time on the 63k-DoF torsion bar (1.04 s against 1.44 s, OpenBLAS, 2 ranks). Kept only
        // once it succeeded: the error estimates reuse a kept factor.
        auto factor = std::make_shared<DirectFactorization>();
        factor->factor(system_matrix, true, true, false);
        factorization = factor;
      }
    factorization->solve(x, system_rhs);
    return 1;
  }

  template <int dim>
  bool LinearElasticProblem<dim>::solve_matrix_free(PETScWrappers::MPI::Vector &x)
  {
    fast_solver::PMultigridSettings settings;
    settings.relative_tolerance = parameters.solver_tolerance;
    settings.max_iterations     = parameters.solver_method == SolverMethod::automatic ?
                                    std::min(parameters.solver_max_iterations, 300u) :
                                    parameters.solver_max_iterations;
    settings.petsc_options      = parameters.petsc_options;
    settings.long_edge_space    = parameters.long_edge_coarse_space;
    settings.reused_degree_one_level = reused_degree_one_level;
    if (warm_start.size() > 0)
      settings.eigenvalue_iterations = 8; // a few iterations from a close guess
    const bool plane_stress     = dim == 2 && parameters.model == Model::plane_stress;
    const auto lame = [&](const types::material_id id) {
      const Material &material = materials.at(id);
      const double    mu       = material.shear_modulus();
      double          lambda   = material.lame_lambda();
      if (plane_stress)
        lambda = 2 * lambda * mu / (lambda + 2 * mu);
      return std::make_pair(lambda * thickness, mu * thickness);
    };
    using Operator = fast_solver::ElasticityOperator<dim, double>;
    using Solver   = fast_solver::PMultigridSolver<dim, Operator>;
    // Integration = reduced: every level of degree >= 2 as the model (the degree-1 level stays full).
    const double hourglass = parameters.reduced_integration ? parameters.hourglass_stiffness : -1.;
    // A dual of the same matrix reuses the primal's solver (keep_solver_for_duals).
    const bool reused = kept_solver != nullptr;
    const auto built  = reused ? kept_solver : std::make_shared<Solver>(
      *mapping, dof_handler,
      [this](const DoFHandler<dim> &dofs, AffineConstraints<double> &level_constraints) {
        // The finest level's are the model's own, held at zero (no rigid boundary here).
        if (&dofs == &dof_handler && rigid_boundaries.empty())
          return level_constraints.copy_from(homogeneous_constraints());
        IndexSet relevant;
        DoFTools::extract_locally_relevant_dofs(dofs, relevant);
        level_constraints.reinit(relevant);
        add_support_constraints(dofs, level_constraints, true);
      },
      [&lame, hourglass](Operator &level_operator, const Mapping<dim> &level_mapping,
                         const DoFHandler<dim> &dofs, const AffineConstraints<double> &level_constraints) {
        level_operator.reinit(level_mapping, dofs, level_constraints, lame, hourglass);
      },
      settings, communicator, reused_lower_multigrid);
    Solver &solver = *built;
    if (keep_solver_for_duals)
      kept_solver = built;
    statistics.preconditioner_setup_seconds = reused ? 0. : solver.statistics().setup_seconds;
    statistics.level_dofs.assign(solver.statistics().level_dofs.begin(),
                                 solver.statistics().level_dofs.end());
    {
      const auto       &s = solver.statistics();
      std::ostringstream note;
      note << "largest cell aspect ratio " << std::setprecision(3) << s.largest_aspect_ratio
           << ": Chebyshev degree " << s.smoothing_degree << " over range " << s.smoothing_range
           << ", " << fast_solver::coarse_level_note(s) << ", kernels on "
           << fast_solver::simd_lanes<double> << " SIMD lane" << (fast_solver::simd_lanes<double> > 1 ? "s" : "")
           << (s.lower_reused ? "; levels of degree <= p, their smoothers and the degree-1 level the degree-p model's" :
               s.coarse_reused ? ", the degree-p model's" : "");
      statistics.multigrid_note = note.str();
    }
    try
      {
        const fast_solver::WarmStart start{warm_start, warm_start_reduction};
        statistics.iterations = solver.solve(system_rhs, constraints, x, warm_start.size() > 0 ? &start : nullptr);
        statistics.initial_residual = solver.statistics().initial_residual;
        statistics.degree_one_reused = solver.statistics().coarse_reused;
        statistics.lower_multigrid_reused = solver.statistics().lower_reused;
        if (parameters.error_estimates) // kept once it has solved: the enriched model's levels below
          degree_one_level = solver.degree_one_level(), multigrid = built;
        statistics.coarse_iterations = solver.statistics().coarse_iterations;
      }
    catch (const SolverControl::NoConvergence &e)
      {
        const std::string what = "matrix-free p-multigrid did not converge in " +
                                 std::to_string(e.last_step) + " iterations (residual " +
                                 std::to_string(e.last_residual) + ")";
        if (parameters.solver_method != SolverMethod::automatic)
          throw std::runtime_error(what + "; try 'Linear solver/Method = direct' or more iterations");
        solver_note += "; " + what + ": solved again with MUMPS (direct)";
        return false;
      }
    return true;
  }

  template <int dim>
  AffineConstraints<double> LinearElasticProblem<dim>::homogeneous_constraints() const
  {
    AffineConstraints<double> homogeneous;
    homogeneous.copy_from(constraints);
    for (const auto &line : constraints.get_lines())
      homogeneous.set_inhomogeneity(line.index, 0.);
    return homogeneous;
  }

  template <int dim>
  PETScWrappers::MPI::Vector LinearElasticProblem<dim>::solve_dual(const PETScWrappers::MPI::Vector &j)
  {
    // solve() reads system_rhs and constraints and writes solution and statistics: the primal's
    // are put back afterwards (the matrix is the same: constraints enter it without their values).
    AffineConstraints<double> primal_constraints;
    primal_constraints.copy_from(constraints);
    const auto primal_rhs        = system_rhs;
    const auto primal_solution   = solution;
    const auto primal_statistics = statistics;
    constraints.copy_from(homogeneous_constraints());
    system_rhs = j;
    solve();
    PETScWrappers::MPI::Vector z = solution;
    constraints.copy_from(primal_constraints);
    system_rhs = primal_rhs;
    solution   = primal_solution;
    statistics = primal_statistics;
    return z;
  }

  template AffineConstraints<double> LinearElasticProblem<2>::homogeneous_constraints() const;
  template AffineConstraints<double> LinearElasticProblem<3>::homogeneous_constraints() const;
  template PETScWrappers::MPI::Vector LinearElasticProblem<2>::solve_dual(const PETScWrappers::MPI::Vector &);
  template PETScWrappers::MPI::Vector LinearElasticProblem<3>::solve_dual(const PETScWrappers::MPI::Vector &);
  template void LinearElasticProblem<2>::choose_solver_method();
  template void LinearElasticProblem<3>::choose_solver_method();
  template void LinearElasticProblem<2>::require_assembled_matrix(const std::string &);
  template void LinearElasticProblem<3>::require_assembled_matrix(const std::string &);
  template void LinearElasticProblem<2>::solve();
  template void LinearElasticProblem<3>::solve();
  template bool LinearElasticProblem<2>::solve_matrix_free(PETScWrappers::MPI::Vector &);
  template bool LinearElasticProblem<3>::solve_matrix_free(PETScWrappers::MPI::Vector &);
} // namespace compliant
