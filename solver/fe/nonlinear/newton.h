// One Newton-Raphson iteration for every nonlinear problem of the solver, on an interface that
// knows nothing of finite elements: a problem linearizes itself at a state, solves for a
// correction and adds it; Newton decides convergence, the line search and when to give up.
// Plain C++ (no deal.II): the finite-strain problem, arc-length continuation and dual problems
// supply the system; the unit tests drive it with a few unknowns.
#pragma once

#include <algorithm>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>

namespace compliant
{
  // A step that did not converge (no convergence, an inverted element, a failed linear solve);
  // the state before the step remains and the path driver cuts the step back.
  struct StepFailure : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  // A step stopped because the run was asked to stop (a signal); not a runtime_error, so that no
  // step cutting catches it. The converged state of the previous step remains.
  struct RunInterrupted : std::exception
  {
    const char *what() const noexcept override { return "interrupted"; }
  };

  struct NewtonReport
  {
    unsigned int iterations       = 0;
    double       residual         = 0;
    double       residual_scale   = 0; // internal force norm the residual is measured against
    unsigned int line_search_cuts = 0;
  };

  struct NewtonSettings
  {
    unsigned int max_iterations     = 25;
    double       residual_tolerance = 1e-9; // relative to the residual scale
    unsigned int line_search_steps  = 5;
    // A correction below this fraction of the state ends the iteration (the residual's round-off floor).
    double correction_tolerance = 1e-10;
    // The line search shortens only steps whose residual exceeds this multiple of the reference:
    // a plain decrease test rejects good steps of slender structures, whose residual rises for an
    // iteration before it collapses.
    double blow_up_factor = 1e3;
    // Inexact Newton: an iterative linear solver need only reduce the residual by a forcing term
    // eta, loose far from the answer and tight near it (forcing_term below). 0: every correction
    // is solved to the system's own tolerance.
    double forcing_max = 0;
  };

  // Eisenstat & Walker's (1996) forcing term, their choice 2 with Kelley's safeguards
  // ("Iterative Methods for Linear and Nonlinear Equations", 1995, sec. 6.3): gamma (r/r_prev)^2,
  // no sharper than gamma eta_prev^2 while that is above 0.1 (one lucky ratio must not make the
  // next solve needlessly exact), at most forcing_max, and at least half the residual Newton still
  // has to remove (a tighter solve is wasted: the iteration stops below `absolute_tolerance`).
  // iteration 0 (no ratio yet): forcing_max.
  inline double forcing_term(const unsigned int iteration, const double residual,
                             const double previous_residual, const double previous_eta,
                             const double absolute_tolerance, const double forcing_max)
  {
    constexpr double gamma = 0.9;
    if (iteration == 0 || !(previous_residual > 0))
      return forcing_max;
    const double ratio = residual / previous_residual;
    double       eta   = gamma * ratio * ratio;
    if (gamma * previous_eta * previous_eta > 0.1)
      eta = std::max(eta, gamma * previous_eta * previous_eta);
    eta = std::min(eta, forcing_max);
    if (residual > 0)
      eta = std::max(eta, 0.5 * absolute_tolerance / residual);
    return std::min(eta, forcing_max);
  }

  // What Newton needs of a problem at a fixed load (or any fixed parameter).
  template <typename VectorType>
  class NewtonSystem
  {
  public:
    virtual ~NewtonSystem() = default;

    struct Linearization
    {
      double residual = 0; // norm of the constrained residual at the state
      double scale    = 0; // the force scale convergence is measured against (iteration > 0)
      // The problem's own conditions of convergence hold at the state (contact: the active set
      // did not change and no node penetrates); a small residual alone is not convergence.
      bool settled = true;
    };
    // Residual (and whatever the correction needs: a tangent, constraints) at state u. The first
    // iteration may impose prescribed values; its scale is not used.
    virtual Linearization linearize(const VectorType &u, unsigned int iteration) = 0;
    // The correction du for the latest linearization. Returns the residual the line search
    // compares against (at least the linearization's: a prescribed increment may be lifted).
    virtual double solve_correction(VectorType &du) = 0;
    // Residual norm at a trial state; may throw StepFailure (an element inverts).
    virtual double trial_residual(const VectorType &u) = 0;
    // u + alpha du (a problem may project, e.g. rigid boundaries onto their exact rigid motion).
    virtual void   add_correction(VectorType &u, double alpha, const VectorType &du) const = 0;
    virtual double norm(const VectorType &v) const = 0;
    // A correction this small (in norm) is round-off of the state itself: Newton has converged as
    // far as the numbers go (a rigid boundary's displacements are differences of positions, so
    // they carry the positions' round-off, eps times the part's size).
    virtual double correction_floor() const { return 0; }
    // Asked before every iteration; true stops with RunInterrupted.
    virtual bool stop_requested() { return false; }
    // The next correction need only reduce the linearization's residual by eta (inexact Newton,
    // NewtonSettings::forcing_max > 0). Direct solvers ignore it.
    virtual void set_forcing(double /*eta*/) {}
  };

  // Newton from u (updated in place on success). Throws StepFailure when it does not converge and
  // RunInterrupted when asked to stop; u is then in an intermediate state, which the caller drops.
  template <typename VectorType>
  NewtonReport newton_solve(NewtonSystem<VectorType> &system, VectorType &u, VectorType &du,
                            const NewtonSettings &settings)
  {
    NewtonReport report;
    double       previous_residual = 0, eta = settings.forcing_max;
    for (unsigned int it = 0; it < settings.max_iterations; ++it)
      {
        if (system.stop_requested())
          throw RunInterrupted();
        const auto linearization = system.linearize(u, it);
        const double r           = linearization.residual;
        report.residual          = r;
        if (it > 0)
          {
            report.residual_scale = std::max(linearization.scale, 1e-300);
            if (r <= settings.residual_tolerance * report.residual_scale && linearization.settled)
              {
                report.iterations = it;
                return report;
              }
          }
        if (!std::isfinite(r))
          throw StepFailure("the residual is not finite");
        if (settings.forcing_max > 0)
          {
            eta = forcing_term(it, r, previous_residual, eta,
                               settings.residual_tolerance * report.residual_scale, settings.forcing_max);
            system.set_forcing(eta);
          }
        previous_residual      = r;
        const double reference = system.solve_correction(du);
        // Backtracking only against a step that inverts elements or blows the residual up by
        // orders of magnitude.
        double alpha = 1;
        for (unsigned int cut = 0; cut < settings.line_search_steps; ++cut)
          {
            VectorType trial = u;
            system.add_correction(trial, alpha, du);
            double trial_norm;
            try
              {
                trial_norm = system.trial_residual(trial);
              }
            catch (const StepFailure &)
              {
                trial_norm = std::numeric_limits<double>::infinity();
              }
            if (trial_norm < settings.blow_up_factor * std::max(reference, report.residual_scale))
              break;
            alpha /= 2;
            ++report.line_search_cuts;
          }
        system.add_correction(u, alpha, du);
        if (it > 0 && linearization.settled &&
            alpha * system.norm(du) <= settings.correction_tolerance * system.norm(u) + system.correction_floor())
          {
            report.iterations = it + 1;
            return report;
          }
      }
    throw StepFailure("Newton did not converge in " + std::to_string(settings.max_iterations) +
                      " iterations (residual " + std::to_string(report.residual) + ")");
  }
} // namespace compliant
