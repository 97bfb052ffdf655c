// Arc-length continuation (Crisfield's spherical constraint, the load factor an unknown): follows
// an equilibrium path of loads through limit points of the load and snap-backs of the
// displacement, where neither a load nor a displacement drive gets through. Each step moves a
// fixed distance s along the path,
//   s^2 = |du|^2 / |t0|^2 + psi^2 dlambda^2   (t0: the initial displacement per unit load factor),
// so that s is measured in load-factor increments of the initial tangent. Every iteration solves
// the tangent for the residual and for the load pattern (one factorization, two right-hand sides)
// and picks the load correction from the constraint's quadratic. The predictor keeps the path's
// direction (Feng's criterion: no turning back at a limit point); the inertia of each converged
// tangent, which the next predictor's factorization gives for free, tells where stability changes:
// a limit point where the load factor turns back (the critical mode is not orthogonal to the
// load), a bifurcation where it does not (orthogonal: the path crosses another branch).
// Plain C++ (no deal.II): the finite-strain problem supplies the system, the unit tests springs
// and trusses with closed-form paths.
#pragma once

#include "nonlinear/newton.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace compliant
{
  struct ArcLengthSettings
  {
    // In load-factor increments along the initial tangent: the first step, the largest and the
    // smallest before the run gives up.
    double initial_step = 0.1, maximum_step = 0.25, minimum_step = 1e-4;
    // Weight of the load factor against the (normalized) displacement in the constraint; 0 is
    // Crisfield's cylindrical form.
    double load_weight = 1;
    // Steps are scaled by sqrt(desired / used) Newton iterations, within [1/2, step_growth].
    unsigned int desired_iterations = 5;
    double       step_growth        = 1.5;
    unsigned int max_iterations     = 25;
    double       residual_tolerance = 1e-9;
    // A correction below this fraction of the state ends the iteration (the residual's round-off floor).
    double correction_tolerance = 1e-10;
    // The path ends where the load factor first reaches end_load_factor (solved there exactly), or
    // after max_steps steps.
    double       end_load_factor = 1;
    unsigned int max_steps       = 500;
    // A step that passes a limit point or bifurcation is taken again from its start in steps this
    // many times shorter, which locate the point closely (1: no second approach).
    double critical_refinement = 8;
  };

  // A change of stability found between two converged steps.
  struct CriticalPoint
  {
    enum class Kind
    {
      limit_point, // the load factor turns back
      bifurcation  // the load factor goes on, the tangent loses (or regains) positive definiteness
    } kind;
    double       load_factor;        // limit point: the extremum of the cubic through both steps
    double       bracket_low, bracket_high; // load factors of the steps either side
    unsigned int step;               // the first step past it
    int          unstable_before, unstable_after; // negative eigenvalues either side (-1: unknown)
  };

  inline std::string to_string(const CriticalPoint::Kind kind)
  {
    return kind == CriticalPoint::Kind::limit_point ? "limit point" : "bifurcation";
  }

  struct ArcLengthStep
  {
    unsigned int number; // 1, 2, ...
    double       load_factor;
    double       arc_length;      // from the start, in the constraint's units
    NewtonReport newton;
    int          unstable_modes;  // negative eigenvalues of the tangent here (-1: unknown)
  };

  struct ArcLengthResult
  {
    unsigned int               steps = 0, cutbacks = 0;
    double                     newton_iterations = 0;
    std::string                failure; // why the path ended before end_load_factor (empty: reached)
    std::string                warning; // the path ended past end_load_factor (not solved there)
    bool                       interrupted = false;
    std::vector<CriticalPoint> critical_points;
  };

  // What continuation needs of a problem: its residual and tangent at any state and load factor.
  template <typename VectorType>
  class ContinuationSystem
  {
  public:
    virtual ~ContinuationSystem() = default;
    struct Linearization
    {
      double residual = 0; // norm of the constrained residual r = f_ext(lambda) - f_int(u)
      double scale    = 0; // the force scale convergence is measured against
      // The problem's own conditions hold at this state (contact: the active set has stopped
      // changing, nothing pulls or penetrates); a state converges only where they do.
      bool settled = true;
      // Constraints were added at this state (contact: free nodes found inside an obstacle are held).
      bool closing = false;
    };
    // Residual and tangent at (u, lambda); throws StepFailure if the state is inadmissible.
    virtual Linearization linearize(const VectorType &u, double lambda) = 0;
    // For the latest linearization: du_residual = K^-1 r and du_load = K^-1 dr/dlambda. Returns
    // the number of negative eigenvalues of K (-1: unknown, e.g. an unsymmetric tangent).
    virtual int solve(VectorType &du_residual, VectorType &du_load) = 0;
    // u + alpha du as the problem updates states (it may project, e.g. rigid boundaries).
    virtual void add_correction(VectorType &u, double alpha, const VectorType &du) const = 0;
    virtual void add(VectorType &y, double a, const VectorType &x) const = 0; // y += a x
    virtual double dot(const VectorType &a, const VectorType &b) const = 0;
    virtual bool   stop_requested() { return false; }
    // A correction this small (in norm) is round-off of the state (NewtonSystem::correction_floor).
    virtual double correction_floor() const { return 0; }
    // A correction (or Newton at a fixed load) starts from a state not in equilibrium.
    virtual void begin_correction() {}
    // Whether the problem has conditions of its own (contact): a step that seemed to pass a
    // critical point may have met one of them instead.
    virtual bool has_own_conditions() const { return false; }
    // The state the path stands on (the start, then every accepted step) and a step abandoned
    // for another from that state: a problem with state of its own (contact's active set) saves
    // and restores it.
    virtual void step_accepted() {}
    virtual void step_abandoned() {}
  };

  namespace arc_length_detail
  {
    // Load factor at the extremum of the cubic Hermite interpolant lambda(s) between two states
    // whose slopes d lambda / d s differ in sign.
    inline double hermite_extremum(double s0, double l0, double d0, double s1, double l1, double d1)
    {
      const double h = s1 - s0;
      if (h <= 0)
        return std::abs(l0) > std::abs(l1) ? l0 : l1;
      // lambda(x) on x in [0, 1]: derivative 3 a x^2 + 2 b x + c
      const double m0 = d0 * h, m1 = d1 * h;
      const double a = 2 * l0 - 2 * l1 + m0 + m1, b = -3 * l0 + 3 * l1 - 2 * m0 - m1, c = m0;
      const auto   value = [&](double x) { return ((a * x + b) * x + c) * x + l0; };
      double       x     = 0.5;
      if (std::abs(a) < 1e-14 * (std::abs(b) + std::abs(c)))
        x = b != 0 ? -c / (2 * b) : 0.5;
      else
        {
          const double disc = std::max(0.0, 4 * b * b - 12 * a * c);
          const double x1 = (-2 * b + std::sqrt(disc)) / (6 * a), x2 = (-2 * b - std::sqrt(disc)) / (6 * a);
          x = (x1 >= 0 && x1 <= 1) ? x1 : x2;
        }
      return value(std::clamp(x, 0.0, 1.0));
    }
  } // namespace arc_length_detail

  namespace arc_length_detail
  {
    // Newton at the fixed load factor target from u (updated on success); false if it fails.
    template <typename VectorType>
    bool solve_at_load(ContinuationSystem<VectorType> &system, VectorType &u, const double target,
                       const ArcLengthSettings &settings, VectorType &correction, VectorType &unused,
                       NewtonReport &report)
    {
      try
        {
          system.begin_correction();
          for (unsigned int it = 0; it <= settings.max_iterations; ++it)
            {
              const auto linearization = system.linearize(u, target);
              if (!std::isfinite(linearization.residual))
                return false;
              if (it > 0 && linearization.settled &&
                  linearization.residual <= settings.residual_tolerance * linearization.scale)
                {
                  report.iterations += it;
                  report.residual = linearization.residual;
                  return true;
                }
              if (it == settings.max_iterations)
                return false;
              system.solve(correction, unused);
              system.add_correction(u, 1, correction);
              // As on the path: a correction at the state's round-off ends it (the residual may not
              // fall further there); not where the problem's own conditions (contact) may still change.
              if (it > 0 && !system.has_own_conditions() &&
                  std::sqrt(system.dot(correction, correction)) <=
                    settings.correction_tolerance * std::sqrt(system.dot(u, u)) + system.correction_floor())
                {
                  // Linearised at the state returned, as every other success: the caller's next
                  // solve takes its tangent and inertia from here.
                  const auto last = system.linearize(u, target);
                  report.iterations += it + 1;
                  report.residual = last.residual;
                  return std::isfinite(last.residual);
                }
            }
        }
      catch (const StepFailure &)
        {}
      return false;
    }
    // Newton on the sphere of radius step about (u, lambda), from the predictor dl * tangent: trial
    // and increment end at the converged state, dl at its load-factor increment. Throws StepFailure
    // when it does not converge (or the sphere misses the path), RunInterrupted when asked to stop.
    template <typename VectorType, typename Inner>
    NewtonReport correct(ContinuationSystem<VectorType> &system, const VectorType &u, const double lambda,
                         const double step, double &dl, const VectorType &tangent, VectorType &trial,
                         VectorType &increment, VectorType &correction, VectorType &load_correction,
                         const Inner &inner, const ArcLengthSettings &settings)
    {
      NewtonReport report;
      trial = u;
      system.add_correction(trial, dl, tangent);
      system.begin_correction();
      for (unsigned int it = 0; it <= settings.max_iterations; ++it)
        {
          if (system.stop_requested())
            throw RunInterrupted();
          increment = trial;
          system.add(increment, -1, u);
          const auto linearization = system.linearize(trial, lambda + dl);
          report.residual          = linearization.residual;
          report.residual_scale    = std::max(linearization.scale, 1e-300);
          if (!std::isfinite(linearization.residual))
            throw StepFailure("the residual is not finite");
          if (it > 0 && linearization.settled &&
              linearization.residual <= settings.residual_tolerance * report.residual_scale)
            {
              report.iterations = it;
              return report;
            }
          if (it == settings.max_iterations)
            break;
          system.solve(correction, load_correction);
          // The new increment (c + d t, dl + d), c = increment + correction, on the sphere of
          // radius step: the root that keeps the increment's direction.
          const double along_c = inner(increment, dl, increment, dl) + inner(increment, 0, correction, 0);
          const double along_t = inner(increment, dl, load_correction, 1);
          const double a       = inner(load_correction, 1, load_correction, 1);
          const double b       = 2 * (along_t + inner(correction, 0, load_correction, 0));
          const double c = inner(increment, dl, increment, dl) + 2 * inner(increment, 0, correction, 0) +
                           inner(correction, 0, correction, 0) - step * step;
          const double discriminant = b * b - 4 * a * c;
          // Where the problem's conditions just changed (a contact node held), the correction may
          // leave the line off the sphere for this iteration: its point nearest the sphere (the
          // real part of the complex roots) is taken, and the next iterations return to it.
          if (discriminant < 0 && linearization.settled)
            throw StepFailure("the arc-length constraint has no real root (the path turns sharply within the step)");
          const double root = std::sqrt(std::max(discriminant, 0.));
          const double d1 = (-b + root) / (2 * a), d2 = (-b - root) / (2 * a);
          // Where contact has just closed, the root with the higher load factor: a load that pushes
          // the part onto an obstacle rises along the contact branch, also where the free path fell
          // (a snap-through caught by a stop), and the other root would pull the contact open.
          const double d = linearization.closing ? std::max(d1, d2) :
                           along_c + d1 * along_t >= along_c + d2 * along_t ? d1 : d2;
          system.add(correction, d, load_correction);
          system.add_correction(trial, 1, correction);
          dl += d;
          // The residual's round-off floor: a correction this small ends the iteration.
          if (it > 0 && std::sqrt(system.dot(correction, correction)) <=
                          settings.correction_tolerance * std::sqrt(system.dot(trial, trial)) +
                            system.correction_floor())
            {
              increment = trial;
              system.add(increment, -1, u);
              // The state the next corrections start from; one whose conditions still change
              // (a contact node held or freed) iterates on.
              if (system.linearize(trial, lambda + dl).settled)
                {
                  report.iterations = it + 1;
                  return report;
                }
            }
        }
      throw StepFailure("no convergence in " + std::to_string(settings.max_iterations) + " iterations (residual " +
                        std::to_string(report.residual) + ")");
    }
    // The critical point found between two converged steps (arc length, load factor and slope
    // d lambda / d s of each): a limit point where the load factor turned, else a bifurcation.
    inline CriticalPoint critical_point(const bool turned, const double s0, const double l0, const double d0,
                                        const double s1, const double l1, const double d1, const unsigned int step,
                                        const int unstable_before, const int unstable_after)
    {
      CriticalPoint point;
      point.kind            = turned ? CriticalPoint::Kind::limit_point : CriticalPoint::Kind::bifurcation;
      point.bracket_low     = std::min(l0, l1);
      point.bracket_high    = std::max(l0, l1);
      point.load_factor     = turned ? hermite_extremum(s0, l0, d0, s1, l1, d1) : 0.5 * (l0 + l1);
      point.step            = step;
      point.unstable_before = unstable_before;
      point.unstable_after  = unstable_after;
      return point;
    }
    // A step that passes the end load factor is replaced by the state at it exactly, corrected from
    // the interpolated one (true). If Newton fails there, the step past the end is kept, linearized
    // again (its linearization must be the last one) and a warning says so (false).
    template <typename VectorType>
    bool land_on_end(ContinuationSystem<VectorType> &system, const VectorType &u, const double lambda, double &dl,
                     VectorType &trial, VectorType &increment, VectorType &correction, VectorType &load_correction,
                     NewtonReport &report, const ArcLengthSettings &settings, std::string &warning)
    {
      const double fraction = (settings.end_load_factor - lambda) / dl;
      VectorType   at_end   = trial; // linearized there
      system.add_correction(at_end, fraction - 1, increment);
      if (solve_at_load(system, at_end, settings.end_load_factor, settings, correction, load_correction, report))
        {
          trial     = at_end;
          increment = at_end;
          system.add(increment, -1, u);
          dl = settings.end_load_factor - lambda;
          return true;
        }
      // The state past the end, with the conditions it holds (a failed Newton may have changed them).
      if (!system.linearize(trial, lambda + dl).settled)
        throw StepFailure("Newton at the end load factor failed, and the step's own state no longer holds its "
                          "contact set");
      warning = "the path ends at load factor " + std::to_string(lambda + dl) + ", past " +
                std::to_string(settings.end_load_factor) + ": Newton at exactly that load factor did not converge";
      return false;
    }
  } // namespace arc_length_detail

  // Follows the path from the converged state (u, lambda), which is updated step by step. on_step
  // runs for every accepted step with its state; on_cutback for every rejected one (the load
  // factor it started from, why, the next step in load-factor units).
  template <typename VectorType>
  ArcLengthResult follow_arc_length(
    ContinuationSystem<VectorType> &system, VectorType &u, double &lambda, const ArcLengthSettings &settings,
    const std::function<void(const ArcLengthStep &, const VectorType &)> &on_step,
    const std::function<void(double, const std::string &, double)>       &on_cutback = {})
  {
    ArcLengthResult result;
    const double    psi2 = settings.load_weight * settings.load_weight;
    VectorType      tangent = u, candidate_tangent = u, correction = u, load_correction = u, increment = u, previous = u, trial = u;

    system.linearize(u, lambda);
    system.step_accepted();
    int          unstable   = system.solve(correction, tangent);
    const double reference2 = system.dot(tangent, tangent); // |t0|^2
    if (!(reference2 > 0) || !std::isfinite(reference2))
      {
        result.failure = "the loads do not move the structure (the load pattern is zero)";
        return result;
      }
    // The constraint's inner product of (du, dlambda) pairs.
    const auto inner = [&](const VectorType &a, double la, const VectorType &b, double lb) {
      return system.dot(a, b) / reference2 + psi2 * la * lb;
    };
    const double unit          = std::sqrt(1 + psi2); // the length of a unit load step along t0
    double       step          = settings.initial_step * unit;
    double       arc_length    = 0;
    bool         have_previous = false;
    double       previous_dl   = 0;
    bool         approaching   = false; // a critical point was found in a step and is approached again
    // The arc length past which an approach that finds nothing ends (what the longer step saw was
    // not there on the path, e.g. a contact node held within it).
    double       approach_ends = 0;
    bool         linearized_here = true; // the system's latest linearization is at (u, lambda)

    // Halves the step after a failure; true when it fell below the minimum (the path stops).
    const auto cut_back = [&](const std::string &why) {
      ++result.cutbacks;
      step /= 2;
      linearized_here = false;
      system.step_abandoned();
      if (on_cutback)
        on_cutback(lambda, why, step / unit);
      if (step >= settings.minimum_step * unit)
        return false;
      std::ostringstream message;
      message << "stopped at load factor " << lambda << " (last converged step): the arc-length step failed ("
              << why << ") and the step fell below Finite strain/Minimum step = " << settings.minimum_step;
      result.failure = message.str();
      return true;
    };
    while (result.steps < settings.max_steps && lambda < settings.end_load_factor)
      {
        if (system.stop_requested())
          {
            result.interrupted = true;
            break;
          }
        // Corrections move the latest linearized state (a problem may linearize constraints there).
        if (!linearized_here)
          system.linearize(u, lambda);
        linearized_here = false;
        // Predictor along the tangent, in the direction of the last step (Feng).
        const double tt   = inner(tangent, 0, tangent, 0);
        const double sign = !have_previous || inner(previous, previous_dl, tangent, 1) >= 0 ? 1 : -1;
        double       dl   = sign * step / std::sqrt(tt + psi2);
        NewtonReport report;
        try
          {
            report = arc_length_detail::correct(system, u, lambda, step, dl, tangent, trial, increment, correction,
                                                load_correction, inner, settings);
          }
        catch (const RunInterrupted &)
          {
            result.interrupted = true;
            break;
          }
        catch (const StepFailure &e)
          {
            if (cut_back(e.what()))
              break;
            continue;
          }
        bool reached_end = false;
        int  unstable_after;
        try
          {
            if (lambda + dl >= settings.end_load_factor && lambda < settings.end_load_factor)
              reached_end = arc_length_detail::land_on_end(system, u, lambda, dl, trial, increment, correction,
                                                           load_correction, report, settings, result.warning);
            // The candidate's tangent (the next predictor) and inertia, from one factorization.
            unstable_after = system.solve(correction, candidate_tangent);
          }
        catch (const StepFailure &e)
          {
            result.warning.clear();
            if (cut_back(e.what()))
              break;
            continue;
          }
        const double tt_after       = inner(candidate_tangent, 0, candidate_tangent, 0);
        const double sign_after     = inner(increment, dl, candidate_tangent, 1) >= 0 ? 1 : -1;
        // d lambda / d s either side, in the direction travelled: opposite signs at a limit point.
        const bool turned  = sign * sign_after < 0;
        const bool changed = unstable >= 0 && unstable_after >= 0 && unstable != unstable_after;
        if ((turned || changed) && !approaching && settings.critical_refinement > 1)
          {
            // Approach it again in shorter steps, so that the cubic locates it closely.
            approaching     = true;
            approach_ends   = system.has_own_conditions() ? arc_length + 1.5 * step :
                                                                  std::numeric_limits<double>::infinity();
            step        = std::max(step / settings.critical_refinement, settings.minimum_step * unit);
            linearized_here = false;
            system.step_abandoned();
            continue; // from the step's start, which is linearized again
          }
        const double lambda_before = lambda, arc_before = arc_length;
        const int    unstable_before = unstable;
        u      = trial;
        lambda = reached_end ? settings.end_load_factor : lambda + dl;
        previous      = increment;
        previous_dl   = dl;
        have_previous = true;
        unstable      = unstable_after;
        std::swap(tangent, candidate_tangent);
        linearized_here = true;
        system.step_accepted();
        arc_length += std::sqrt(inner(increment, dl, increment, dl));
        ++result.steps;
        result.newton_iterations += report.iterations;
        if (turned || changed)
          {
            approaching = false;
            result.critical_points.push_back(arc_length_detail::critical_point(
              turned, arc_before, lambda_before, sign / std::sqrt(tt + psi2), arc_length, lambda,
              sign_after / std::sqrt(tt_after + psi2), result.steps, unstable_before, unstable));
          }
        if (approaching && arc_length > approach_ends)
          approaching = false;
        on_step({result.steps, lambda, arc_length, report, unstable}, u);
        const double used = std::max<unsigned int>(report.iterations, 1);
        // No growth while a critical point is approached in short steps.
        step *= std::clamp(std::sqrt(settings.desired_iterations / used), 0.5, approaching ? 1.0 : settings.step_growth);
        step = std::min(step, settings.maximum_step * unit);
      }
    if (result.failure.empty() && !result.interrupted && lambda < settings.end_load_factor)
      {
        std::ostringstream message;
        message << "the path did not reach load factor " << settings.end_load_factor << " in "
                << settings.max_steps << " arc-length steps (it is at " << lambda << ")";
        result.failure = message.str();
      }
    return result;
  }
} // namespace compliant
