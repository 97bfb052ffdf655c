// The path driver of load-controlled nonlinear analyses: load factor from its current value to 1
// in adaptive steps, each solved by the problem's Newton. A step that fails (no convergence, an
// inverted element) or jumps to a distant equilibrium is cut back and retried; easy steps grow.
// After each step the stability check may stop the path at a limit point or bifurcation.
// Plain C++ (no deal.II): the analysis supplies the problem and what to do with each step.
#pragma once

#include "nonlinear/newton.h"

#include <functional>
#include <string>

namespace compliant
{
  struct LoadSteppingSettings
  {
    double initial_step = 0.1, minimum_step = 1e-4, maximum_step = 0.25;
    // A converged step whose state change per load increment exceeds this multiple of the last
    // accepted step's may have jumped to a distant equilibrium (snap-through past a limit point):
    // it is cut back. The retry is accepted if its rate did not grow by more than
    // continuous_rate_growth over the rejected attempt's: on a continuous (if fast) path the rate
    // settles as the step shrinks, while a jump of fixed size doubles it with every halving.
    double jump_factor            = 3;
    double continuous_rate_growth = 1.3;
    // Steps that converge within this many Newton iterations let the next one grow by step_growth.
    unsigned int easy_newton_iterations = 6;
    double       step_growth            = 1.5;
    bool         stability_check        = true;
    // What the stability stop advises; the analysis knows how the path is driven.
    std::string unstable_advice = "Drive the structure by a prescribed displacement to follow it past the limit point";
  };

  // The problem as the path driver sees it.
  class LoadPathProblem
  {
  public:
    virtual ~LoadPathProblem() = default;
    virtual double load_factor() const = 0;
    // Newton to the load factor; on failure throws StepFailure with the state unchanged.
    virtual NewtonReport solve_to(double load_factor) = 0;
    // Remembers the current (converged) state, and returns to it.
    virtual void save_state()    = 0;
    virtual void restore_state() = 0;
    // Norm of the change from the saved state to the current one.
    virtual double change_from_saved_state() const = 0;
    // Negative eigenvalues of the tangent at the current state (0: stable equilibrium).
    virtual unsigned int unstable_modes() = 0;
    // Asked before every step; true stops the path (RunInterrupted).
    virtual bool stop_requested() { return false; }
  };

  struct AcceptedStep
  {
    unsigned int number; // 1, 2, ...
    double       load_factor;
    NewtonReport newton;
  };

  struct LoadPathResult
  {
    unsigned int steps = 0, cutbacks = 0;
    double       newton_iterations = 0;
    // Why the path ended before load factor 1 (empty: it reached 1).
    std::string failure;
    bool        interrupted             = false;
    double      last_stable_load_factor = -1; // set when the stability check stopped the path
  };

  // Follows the load path. on_step runs for every accepted step (the curve, quantities), after
  // the stability check; on_cutback for every rejected one (the target, why, the next increment).
  LoadPathResult follow_load_path(LoadPathProblem &problem, const LoadSteppingSettings &settings,
                                  const std::function<void(const AcceptedStep &)> &on_step,
                                  const std::function<void(double, const std::string &, double)> &on_cutback = {});
} // namespace compliant
