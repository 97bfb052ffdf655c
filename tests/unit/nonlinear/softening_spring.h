// A one-unknown problem with a closed-form limit point, for the Newton iteration and the path
// driver: the softening spring f(u) = u - 1.5 u^2 + 0.6 u^3 under the load lambda P. Its stiffness
// f'(u) = 1 - 3 u + 1.8 u^2 vanishes at u = (3 - sqrt(1.8)) / 3.6, where f = 0.201003...
#pragma once

#include "nonlinear/newton.h"

#include <cmath>
#include <functional>

namespace softening_spring
{
  inline double force(double u) { return u - 1.5 * u * u + 0.6 * u * u * u; }
  inline double stiffness(double u) { return 1 - 3 * u + 1.8 * u * u; }
  inline double limit_displacement() { return (3 - std::sqrt(1.8)) / 3.6; }
  inline double limit_force() { return force(limit_displacement()); }

  // Newton's view at a fixed load. Options: a state beyond which the "element inverts" (the
  // residual throws StepFailure) and a tangent scaled down in the first iteration (an overshoot).
  struct System : compliant::NewtonSystem<double>
  {
    double                load;
    double                invalid_above         = 1e300;
    double                first_tangent_scale   = 1;
    // An inexact linear solver as poor as inexact Newton allows: the correction leaves the
    // fraction eta (the forcing term) of the residual unsolved.
    bool                  inexact               = false;
    double                eta                   = 0;
    std::vector<double>   forcing_terms;
    std::function<bool()> stop                  = [] { return false; };
    std::vector<double>   residuals;
    double                residual = 0, tangent = 1;
    unsigned int          iteration = 0;

    explicit System(double load) : load(load) {}

    double evaluate(double u) const
    {
      if (u > invalid_above)
        throw compliant::StepFailure("inverted");
      return load - force(u);
    }
    Linearization linearize(const double &u, unsigned int it) override
    {
      residual  = evaluate(u);
      tangent   = stiffness(u) * (it == 0 ? first_tangent_scale : 1);
      iteration = it;
      residuals.push_back(std::abs(residual));
      return {std::abs(residual), std::max(std::abs(load), 1e-3)};
    }
    double solve_correction(double &du) override
    {
      du = (inexact ? 1 - eta : 1.) * residual / tangent;
      return std::abs(residual);
    }
    double trial_residual(const double &u) override { return std::abs(evaluate(u)); }
    void   add_correction(double &u, double alpha, const double &du) const override { u += alpha * du; }
    double norm(const double &v) const override { return std::abs(v); }
    bool   stop_requested() override { return stop(); }
    void   set_forcing(double forcing) override
    {
      eta = forcing;
      forcing_terms.push_back(forcing);
    }
  };
} // namespace softening_spring
