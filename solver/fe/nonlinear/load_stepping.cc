#include "nonlinear/load_stepping.h"

#include <algorithm>
#include <sstream>

namespace compliant
{
  LoadPathResult follow_load_path(LoadPathProblem &problem, const LoadSteppingSettings &settings,
                                  const std::function<void(const AcceptedStep &)> &on_step,
                                  const std::function<void(double, const std::string &, double)> &on_cutback)
  {
    LoadPathResult result;
    // Maximum step bounds the first step too.
    double step          = std::min(settings.initial_step, settings.maximum_step);
    double previous_rate = 0; // state change per load increment of the last accepted step
    double rejected_rate = 0; // that of the last attempt rejected as a jump from the same state
    while (problem.load_factor() < 1 - 1e-12)
      {
        const double target = std::min(1.0, problem.load_factor() + step);
        bool         jumped = false;
        try
          {
            if (problem.stop_requested())
              throw RunInterrupted();
            const double previous = problem.load_factor();
            problem.save_state();
            const NewtonReport report = problem.solve_to(target);
            const double       rate   = problem.change_from_saved_state() / (target - previous);
            const bool         fast   = previous_rate > 0 && rate > settings.jump_factor * previous_rate;
            const bool settled = rejected_rate > 0 && rate <= settings.continuous_rate_growth * rejected_rate;
            if (fast && !settled)
              {
                problem.restore_state();
                rejected_rate = rate;
                jumped        = true;
                throw StepFailure("the displacement jumped " + std::to_string(rate / previous_rate) +
                                  " times faster than in the previous step (snap-through "
                                  "past a limit point?)");
              }
            previous_rate = rate;
            rejected_rate = 0;
            ++result.steps;
            if (settings.stability_check)
              if (const unsigned int unstable = problem.unstable_modes(); unstable > 0)
                {
                  std::ostringstream message;
                  message << "equilibrium turned unstable between load factors " << previous << " and "
                          << target << ": the tangent stiffness has " << unstable
                          << " negative eigenvalue(s) (limit point or bifurcation); the last stable "
                          << "load factor is " << previous << ". " << settings.unstable_advice;
                  result.failure                 = message.str();
                  result.last_stable_load_factor = previous;
                }
            result.newton_iterations += report.iterations;
            on_step({result.steps, target, report});
            if (!result.failure.empty())
              break;
            if (report.iterations <= settings.easy_newton_iterations)
              step = std::min(settings.maximum_step, settings.step_growth * step);
          }
        catch (const RunInterrupted &)
          {
            result.interrupted = true;
            break;
          }
        catch (const StepFailure &e)
          {
            if (!jumped)
              rejected_rate = 0; // another failure: no rate to compare the retry with
            ++result.cutbacks;
            if (on_cutback)
              on_cutback(target, e.what(), step / 2);
            step /= 2;
            if (step < settings.minimum_step)
              {
                std::ostringstream message;
                message << "stopped at load factor " << problem.load_factor()
                        << " (last converged step): the step to " << target << " failed (" << e.what()
                        << ") and the increment fell below Finite strain/Minimum "
                        << "step = " << settings.minimum_step;
                result.failure = message.str();
                break;
              }
          }
      }
    return result;
  }
} // namespace compliant
