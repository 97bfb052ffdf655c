// The finite-strain problem as a ContinuationSystem: residual and tangent at any state and load
// factor, the load pattern dr/dlambda (the residual is affine in lambda: dead and follower loads,
// rigid-boundary forces and moments), both solves with one MUMPS factorization, whose LDL^T
// inertia is the stability count. The continuation itself is nonlinear/arc_length.h.
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>

#include "linear_algebra/direct_factorization.h"

#include <cstdlib>
#include <iostream>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  class FiniteStrainContinuationSystem : public ContinuationSystem<PETScWrappers::MPI::Vector>
  {
  public:
    using Vector = PETScWrappers::MPI::Vector;

    explicit FiniteStrainContinuationSystem(FiniteStrainProblem<dim> &problem)
      : p(problem)
      , rhs(p.locally_owned_dofs, p.communicator)
      , full(p.locally_owned_dofs, p.communicator)
      , load(p.locally_owned_dofs, p.communicator)
      , ghosted(p.locally_owned_dofs, p.locally_relevant_dofs, p.communicator)
      , at_lambda(p.locally_owned_dofs, p.communicator)
      // A follower pressure, and a moment on a rigid boundary in 3D, make the tangent unsymmetric.
      , symmetric(p.follower_pressures.empty() && !(dim == 3 && !p.rigid_boundaries.empty()))
    {
      const auto per_component = DoFTools::count_dofs_per_fe_component(p.dof_handler);
      pressure_dofs            = p.mixed ? per_component.back() : 0;
    }

    Linearization linearize(const Vector &u, const double lambda) override
    {
      ghosted      = u;
      bool settled = true, closing = false;
      if (p.contact)
        settled = update_contact(lambda, closing);
      // With contact the held nodes' lines close their gaps (n . du = -gap) in the correction;
      // the load's solve keeps them where they are (homogeneous lines).
      constraints = p.make_constraints(lambda, !p.contact, ghosted);
      if (p.contact)
        load_constraints = p.make_constraints(lambda, true, ghosted);
      Timer timer;
      p.assemble(ghosted, lambda, &constraints, true, rhs, &full);
      // r(lambda + 1) - r(lambda): exact, the residual being affine in lambda. Without a matrix the
      // assembly does not lift inhomogeneities: both residuals are taken that way.
      if (p.contact)
        {
          p.assemble(ghosted, lambda, &load_constraints, false, at_lambda);
          p.assemble(ghosted, lambda + 1, &load_constraints, false, load);
          load.add(-1, at_lambda);
        }
      else
        {
          p.assemble(ghosted, lambda + 1, &constraints, false, load);
          load.add(-1, rhs);
        }
      p.tangent_assembly_seconds += timer.wall_time();
      const double residual = p.residual_norm_of(rhs), scale = p.residual_norm_of(full),
                   load_norm = p.residual_norm_of(load);
      near_equilibrium      = residual <= p.contact_release_residual * scale;
      ++iteration;
      if (std::getenv("COMPLIANT_DEBUG_NEWTON") && Utilities::MPI::this_mpi_process(p.communicator) == 0)
        std::cout << "    lambda " << lambda << " residual " << residual << " scale " << scale << " load "
                  << load_norm << (settled ? "" : " (contact changing)") << std::endl;
      Linearization result;
      result.residual = residual;
      result.scale    = scale;
      result.settled  = settled;
      result.closing  = closing;
      return result;
    }

    void begin_correction() override { iteration = 0; }
    bool has_own_conditions() const override { return p.contact != nullptr; }
    // The obstacles' and the pairs' active sets of the state the path stands on.
    void step_accepted() override { p.start_contact_step(); }
    void step_abandoned() override { p.restore_contact_state(); }

    int solve(Vector &du_residual, Vector &du_load) override
    {
      Timer        timer;
      unsigned int negative = 0;
      try
        {
          factorization.factor(p.tangent, symmetric);
          du_residual = 0;
          du_load     = 0;
          factorization.solve(du_residual, rhs);
          factorization.solve(du_load, load);
          if (symmetric)
            negative = factorization.negative_eigenvalues();
        }
      catch (const std::runtime_error &e)
        {
          throw StepFailure(e.what());
        }
      p.total_linear_solves += 2;
      p.linear_solve_seconds += timer.wall_time();
      constraints.distribute(du_residual);
      (p.contact ? load_constraints : constraints).distribute(du_load);
      if (!symmetric)
        return -1;
      // K_pp = -M/lambda is negative definite: inertia(K) = inertia(K_pp) + inertia(Schur complement)
      return negative > pressure_dofs ? negative - pressure_dofs : 0;
    }

    void add_correction(Vector &u, const double alpha, const Vector &du) const override
    {
      p.add_correction(u, alpha, du);
    }
    void   add(Vector &y, const double a, const Vector &x) const override { y.add(a, x); }
    double dot(const Vector &a, const Vector &b) const override { return p.unknown_dot(a, b); }
    double correction_floor() const override { return p.correction_round_off(); }
    bool   stop_requested() override { return p.stop_requested && p.stop_requested(); }

  private:
    // The contact active set at the state in `ghosted`: true when it no longer changes, nothing
    // pulls and nothing penetrates beyond the tolerance. Contact forces free a node only once the
    // corrections are near equilibrium for the set.
    bool update_contact(const double lambda, bool &closing)
    {
      const auto update = p.update_contact_set(ghosted, lambda, iteration > 0 && near_equilibrium, full);
      closing           = update.closed > 0;
      return update.changes == 0 && update.pulling == 0 && update.violation <= p.contact->tolerance;
    }

    FiniteStrainProblem<dim>  &p;
    Vector                     rhs, full, load, ghosted, at_lambda;
    AffineConstraints<double>  constraints, load_constraints;
    unsigned int               iteration        = 0;
    bool                       near_equilibrium = false;
    DirectFactorization        factorization;
    const bool                 symmetric;
    types::global_dof_index    pressure_dofs = 0;
  };

  template <int dim>
  void FiniteStrainProblem<dim>::require_load_driven() const
  {
    PETScWrappers::MPI::Vector zero(locally_owned_dofs, locally_relevant_dofs, communicator);
    const bool driven = make_constraints(1, false, zero).has_inhomogeneities();
    if (Utilities::MPI::max(driven ? 1 : 0, communicator) > 0)
      throw std::invalid_argument(
        "Finite strain/Path = arc length follows loads (forces, moments, pressures), but Boundary "
        "conditions prescribe a nonzero displacement or rotation, which drives the path itself: "
        "use Path = load steps for a displacement drive, or load the structure instead");
  }

  template <int dim>
  ArcLengthResult FiniteStrainProblem<dim>::follow_arc_length(
    const ArcLengthSettings &arc_settings, const std::function<void(const ArcLengthStep &)> &on_step,
    const std::function<void(double, const std::string &, double)> &on_cutback)
  {
    require_load_driven();
    FiniteStrainContinuationSystem<dim> system(*this);
    PETScWrappers::MPI::Vector          u(locally_owned_dofs, communicator);
    u             = solution;
    double lambda = load_factor;
    return compliant::follow_arc_length<PETScWrappers::MPI::Vector>(
      system, u, lambda, arc_settings,
      [&](const ArcLengthStep &step, const PETScWrappers::MPI::Vector &state) {
        solution                = state;
        load_factor             = step.load_factor;
        secant.load_factor_then = -1; // not a step of solve_to: no secant from here
        on_step(step);
      },
      on_cutback);
  }

  template void FiniteStrainProblem<2>::require_load_driven() const;
  template void FiniteStrainProblem<3>::require_load_driven() const;
  template ArcLengthResult FiniteStrainProblem<2>::follow_arc_length(
    const ArcLengthSettings &, const std::function<void(const ArcLengthStep &)> &,
    const std::function<void(double, const std::string &, double)> &);
  template ArcLengthResult FiniteStrainProblem<3>::follow_arc_length(
    const ArcLengthSettings &, const std::function<void(const ArcLengthStep &)> &,
    const std::function<void(double, const std::string &, double)> &);
} // namespace compliant
