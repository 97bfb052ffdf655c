// The finite-strain problem as a NewtonSystem: linearize (constraints at the current state,
// residual, tangent or the matrix-free operator), solve for the correction (matrix-free
// p-multigrid, CG + GAMG or MUMPS, falling back to MUMPS for good when an iterative solve fails),
// trial residuals for the line search. The iteration itself is nonlinear/newton.h.
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/base/timer.h>

#include "fast_solver/p_multigrid_solver.h"
#include "fast_solver/tangent_operator.h"
#include "linear_algebra/petsc_linear_solver.h"
#include "linear_algebra/rigid_body_modes.h"

#include <cstdlib>
#include <iostream>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  class FiniteStrainNewtonSystem : public NewtonSystem<PETScWrappers::MPI::Vector>
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    FiniteStrainNewtonSystem(FiniteStrainProblem<dim> &problem, const double target)
      : p(problem)
      , target(target)
      , rhs(p.locally_owned_dofs, p.communicator)
      , full(p.locally_owned_dofs, p.communicator)
      , ghosted(p.locally_owned_dofs, p.locally_relevant_dofs, p.communicator)
      , amg{SolverMethod::cg_amg, 1e-10, 500, p.parameters.petsc_options}
      , trial_ghosted(p.locally_owned_dofs, p.locally_relevant_dofs, p.communicator)
    {
      ghosted     = p.solution;
      homogeneous = p.make_constraints(target, true, ghosted);
      // Newton steps by CG + GAMG on the tangent (block size, rigid-body modes of the reference
      // configuration as near null space) only when asked: on a 3D TPU leaf of 5e4 DoFs it took
      // 108 s against MUMPS's 78 s (README, Speed). MUMPS again if CG fails (an indefinite
      // tangent near a limit point breaks CG); not on the unsymmetric tangent of a 3D rigid
      // boundary under a moment.
      iterative = !p.mixed && !p.iterative_failed && p.parameters.solver_method == SolverMethod::cg_amg &&
                  !(dim == 3 && !p.rigid_boundaries.empty());
      if (iterative)
        modes = rigid_body_modes(*p.mapping, p.dof_handler, p.communicator);
    }

    Linearization linearize(const Vector &u, const unsigned int iteration) override
    {
      ghosted     = u;
      bool settled = true;
      if (p.contact)
        {
          // The active set at this state, from its contact forces (the unconstrained residual);
          // the line search then measures residuals with it.
          const auto update = p.update_contact_set(ghosted, target, near_equilibrium, full);
          settled = update.changes == 0 && update.pulling == 0 && update.violation <= p.contact->tolerance;
          homogeneous = p.make_constraints(target, true, ghosted);
        }
      constraints = p.make_constraints(target, false, ghosted);
      matrix_free = p.matrix_free_tangent();
      if (matrix_free && iteration > 0 && is_last_trial(u))
        {
          // Newton took the full step the line search tried: its residual is this state's.
          rhs.swap(trial_rhs);
          full.swap(trial_full);
        }
      else
        {
          Timer assembly_timer;
          p.assemble(ghosted, target, &constraints, !matrix_free, rhs, iteration > 0 ? &full : nullptr);
          p.tangent_assembly_seconds += assembly_timer.wall_time();
        }
      has_trial = false;
      Linearization result;
      result.settled  = settled;
      result.residual = last_residual = p.residual_norm_of(rhs);
      if (std::getenv("COMPLIANT_DEBUG_NEWTON"))
        {
          const double scale = iteration > 0 ? p.residual_norm_of(full) : 0.; // collective
          if (Utilities::MPI::this_mpi_process(p.communicator) == 0)
            std::cout << "    it " << iteration << " residual " << result.residual << " scale " << scale
                      << std::endl;
        }
      // Force scale of the convergence test: internal forces including the reactions.
      if (iteration > 0)
        result.scale = p.residual_norm_of(full);
      // Contact forces are trusted to free a node once Newton is near equilibrium for the set.
      near_equilibrium = iteration > 0 && result.residual <= p.contact_release_residual * result.scale;
      return result;
    }

    double solve_correction(Vector &du) override
    {
      du = 0;
      // The residual the line search measures against: with the prescribed increment moved to
      // the right-hand side (the assembled path does that in the residual itself).
      double reference = last_residual;
      Timer  solve_timer;
      if (matrix_free)
        try
          {
            p.total_linear_iterations += p.solve_matrix_free(ghosted, rhs, constraints, du);
            reference = std::max(last_residual, p.tangent_multigrid->statistics().lifted_rhs_norm);
          }
        catch (const std::exception &e)
          {
            // An indefinite tangent (past a limit point) or a failed level state: the exact
            // solver from here on, with the tangent assembled after all.
            fall_back_to_direct("matrix-free p-multigrid", e.what());
            p.tangent_multigrid.reset();
            Timer reassembly_timer;
            p.assemble(ghosted, target, &constraints, true, rhs);
            p.tangent_assembly_seconds += reassembly_timer.wall_time();
            du = 0;
            p.solve_direct(du, rhs);
          }
      else if (iterative && !p.iterative_failed)
        try
          {
            p.total_linear_iterations += solve_linear_system(p.tangent, du, rhs, modes, amg, dim);
          }
        catch (const std::runtime_error &e)
          {
            fall_back_to_direct("CG + GAMG", e.what());
            du = 0;
            p.solve_direct(du, rhs);
          }
      else
        p.solve_direct(du, rhs);
      ++p.total_linear_solves;
      p.linear_solve_seconds += solve_timer.wall_time();
      constraints.distribute(du);
      return reference;
    }

    double trial_residual(const Vector &u) override
    {
      // Where nothing but the state changes the residual (no rigid boundary linearised at u, no
      // active set), keep it: the next linearization at this state needs the same vectors.
      // Without a matrix the constrained rows are zeroed alike by the homogeneous constraints
      // and by the inhomogeneous ones, whose lines are the same.
      if (!matrix_free || p.contact || !p.rigid_boundaries.empty())
        return p.residual_norm(u, target, homogeneous);
      trial_state = u;
      trial_ghosted = u;
      if (trial_rhs.size() == 0)
        {
          trial_rhs.reinit(p.locally_owned_dofs, p.communicator);
          trial_full.reinit(p.locally_owned_dofs, p.communicator);
        }
      p.assemble(trial_ghosted, target, &homogeneous, false, trial_rhs, &trial_full);
      has_trial = true;
      return p.residual_norm_of(trial_rhs);
    }

    void add_correction(Vector &u, const double alpha, const Vector &du) const override
    {
      p.add_correction(u, alpha, du);
    }

    double norm(const Vector &v) const override { return std::sqrt(p.unknown_dot(v, v)); }

    double correction_floor() const override { return p.correction_round_off(); }

    bool stop_requested() override { return p.stop_requested && p.stop_requested(); }

    void set_forcing(const double eta) override { p.linear_forcing = eta; }

  private:
    // Whether u is the state of the last trial residual, to the bit.
    bool is_last_trial(const Vector &u)
    {
      if (!has_trial)
        return false;
      Vector difference(u);
      difference -= trial_state;
      return difference.linfty_norm() == 0;
    }

    void fall_back_to_direct(const std::string &which, const std::string &why)
    {
      p.iterative_failed  = true;
      p.iterative_failure = why;
      if (Utilities::MPI::this_mpi_process(p.communicator) == 0)
        std::cout << "Linear solver: " << which << " failed on the tangent (" << why << "); MUMPS from here on"
                  << std::endl;
    }

    FiniteStrainProblem<dim>       &p;
    const double                    target;
    Vector                          rhs, full, ghosted;
    AffineConstraints<double>       homogeneous, constraints;
    const LinearSolverSettings      amg;
    bool                            iterative = false, matrix_free = false;
    std::vector<Vector>             modes;
    double                          last_residual = 0;
    // The last trial state of the line search, and its residuals (constrained and full).
    Vector                          trial_state, trial_ghosted, trial_rhs, trial_full;
    bool                            has_trial = false;
    bool                            near_equilibrium = false;
  };

  template <int dim>
  NewtonReport FiniteStrainProblem<dim>::solve_to(const double target)
  {
    NewtonSettings newton;
    newton.max_iterations     = settings.max_newton_iterations;
    newton.residual_tolerance = settings.residual_tolerance;
    newton.line_search_steps  = settings.line_search_steps;
    newton.forcing_max        = newton_forcing_max;
    PETScWrappers::MPI::Vector u(locally_owned_dofs, communicator), du(locally_owned_dofs, communicator);
    bool         predicted     = predict_by_secant(target, u);
    unsigned int wasted_solves = 0; // of a failed attempt from the predictor: counted in the report
    NewtonReport report;
    for (;;)
      {
        const unsigned int solves_before = total_linear_solves;
        try
          {
            if (!predicted)
              u = solution;
            FiniteStrainNewtonSystem<dim> system(*this, target);
            report = newton_solve(system, u, du, newton);
            report.iterations += wasted_solves;
            break;
          }
        catch (const std::runtime_error &e)
          {
            // solution is untouched: the converged state of the previous step remains, and so does
            // its friction state (stick, slip, anchors) rather than the failed Newton's
            restore_contact_state();
            newton_factorization.reset();
            if (!predicted)
              throw StepFailure(e.what());
            // The secant overshot (an inverted element, a far state): again from the last state.
            predicted     = false;
            wasted_solves = total_linear_solves - solves_before;
            if (Utilities::MPI::this_mpi_process(communicator) == 0)
              std::cout << "  step to load factor " << target << ": Newton from the secant predictor failed ("
                        << e.what() << "), again from the last state" << std::endl;
          }
      }
    if (target > load_factor)
      {
        secant.start             = solution;
        secant.load_factor_start = load_factor;
        secant.load_factor_then  = target;
      }
    else
      secant.load_factor_then = -1;
    // The factor serves this step's iterations only: the stability check, a buckling or dual
    // solve and the next step's growing tangent must not find a second one held beside theirs.
    newton_factorization.reset();
    solution    = u;
    load_factor = target;
    return report;
  }

  template <int dim>
  bool FiniteStrainProblem<dim>::predict_by_secant(const double target, PETScWrappers::MPI::Vector &u) const
  {
    // Measured on cases/benchmarks/flexure_finite_strain.prm: see the README (Speed).
    if (!settings.secant_predictor || contact || secant.load_factor_then != load_factor || !(target > load_factor) ||
        !(load_factor > secant.load_factor_start))
      return false;
    double ratio = (target - load_factor) / (load_factor - secant.load_factor_start);
    // A test hook (case.finite_strain_secant_fallback): a secant stretched this many times makes
    // Newton fail from it, so that the retry from the last state is exercised.
    if (const char *stretch = std::getenv("COMPLIANT_TEST_SECANT_STRETCH"))
      ratio *= std::atof(stretch);
    u = solution;
    u.add(ratio, solution);
    u.add(-ratio, secant.start);
    return true;
  }

  template NewtonReport FiniteStrainProblem<2>::solve_to(double);
  template NewtonReport FiniteStrainProblem<3>::solve_to(double);
} // namespace compliant
