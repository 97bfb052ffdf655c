// The generic Newton iteration on a spring with a closed-form answer: quadratic convergence, the
// line search against an inverting step, no convergence past the limit load, interruption.
#include "nonlinear/newton.h"

#include <gtest/gtest.h>

#include "softening_spring.h"

using namespace compliant;
namespace ss = softening_spring;

TEST(Newton, ConvergesQuadraticallyToTheEquilibrium)
{
  ss::System     system(0.15);
  double         u = 0, du = 0;
  NewtonSettings settings;
  settings.residual_tolerance = 1e-13;
  const NewtonReport report = newton_solve(system, u, du, settings);
  EXPECT_NEAR(ss::force(u), 0.15, 1e-13);
  EXPECT_LE(report.iterations, 6u);
  EXPECT_EQ(report.line_search_cuts, 0u);
  // Quadratic: r_{k+1} <= C r_k^2 with C of order f'' / (2 f') once close.
  const auto &r = system.residuals;
  ASSERT_GE(r.size(), 3u);
  for (std::size_t k = 1; k + 1 < r.size(); ++k)
    {
      if (r[k + 1] > 1e-15)
        {
          EXPECT_LT(r[k + 1], 10 * r[k] * r[k]) << "iteration " << k;
        }
    }
}

TEST(Newton, LineSearchShortensAStepThatInverts)
{
  // The load f(0.4036) = 0.1987; the first tangent, a sixth of the true one, sends the state to
  // 1.19 and, halved, 0.60, beyond 0.5 where the residual fails; the second halving brings it back.
  ss::System system(ss::force(0.4036));
  system.invalid_above       = 0.5;
  system.first_tangent_scale = 1. / 6;
  double u = 0, du = 0;
  const NewtonReport report = newton_solve(system, u, du, NewtonSettings{});
  EXPECT_EQ(report.line_search_cuts, 2u);
  EXPECT_NEAR(u, 0.4036, 1e-8);
}

// Beyond the limit load Newton from the unloaded state either gives up or lands on the far,
// stiffening branch (u > 1.206): a snap-through the path driver has to recognise as a jump.
TEST(Newton, BeyondTheLimitLoadJumpsOrGivesUp)
{
  const double load = 1.2 * ss::limit_force();
  {
    ss::System system(load);
    double     u = 0, du = 0;
    newton_solve(system, u, du, NewtonSettings{});
    EXPECT_GT(u, (3 + std::sqrt(1.8)) / 3.6);
    EXPECT_NEAR(ss::force(u), load, 1e-9);
  }
  ss::System     system(load);
  double         u = 0, du = 0;
  NewtonSettings settings;
  settings.max_iterations = 3;
  try
    {
      newton_solve(system, u, du, settings);
      FAIL() << "converged in 3 iterations to u = " << u;
    }
  catch (const StepFailure &e)
    {
      EXPECT_NE(std::string(e.what()).find("did not converge in 3 iterations"), std::string::npos) << e.what();
    }
}

TEST(Newton, StopsWhenAsked)
{
  ss::System system(0.1);
  int        asked = 0;
  system.stop      = [&] { return ++asked > 1; };
  double u = 0, du = 0;
  EXPECT_THROW(newton_solve(system, u, du, NewtonSettings{}), RunInterrupted);
  EXPECT_EQ(system.residuals.size(), 1u);
}

// A problem whose own conditions are not yet met (contact: the active set still changes) is not
// converged however small its residual: Newton goes on until the problem says it is settled.
TEST(Newton, WaitsUntilTheProblemIsSettled)
{
  struct Unsettled : ss::System
  {
    using ss::System::System;
    unsigned int calls = 0;
    Linearization linearize(const double &u, unsigned int it) override
    {
      auto result    = ss::System::linearize(u, it);
      result.settled = ++calls > 6; // long after the residual has reached round-off
      return result;
    }
  };
  Unsettled      system(0.15);
  double         u = 0, du = 0;
  const NewtonReport report = newton_solve(system, u, du, NewtonSettings{});
  EXPECT_EQ(report.iterations, 6u);
  EXPECT_NEAR(ss::force(u), 0.15, 1e-12);
}

// Eisenstat-Walker's choice 2: the square of the residual ratio, kept from collapsing after one
// lucky ratio, at most the maximum, and never tighter than half the residual still to remove.
TEST(Newton, ForcingTermFollowsEisenstatWalkerWithSafeguards)
{
  EXPECT_EQ(forcing_term(0, 1., 0., 0., 1e-9, 1e-2), 1e-2);               // no ratio yet
  EXPECT_NEAR(forcing_term(3, 1e-2, 1., 1e-3, 1e-12, 1e-1), 0.9e-4, 1e-15); // 0.9 (r / r_prev)^2
  EXPECT_EQ(forcing_term(3, 0.9, 1., 1e-3, 1e-12, 1e-2), 1e-2);            // slow: the maximum
  // A lucky ratio after a loose solve (0.9 * 0.5^2 > 0.1): no sharper than 0.9 eta_prev^2.
  EXPECT_NEAR(forcing_term(3, 1e-6, 1., 0.5, 1e-12, 1.), 0.9 * 0.25, 1e-15);
  // Close to the tolerance: half of what is left to remove, not the quadratic 0.9e-8.
  EXPECT_NEAR(forcing_term(4, 1e-4, 1., 1e-3, 1e-8, 1e-1), 0.5e-4, 1e-15);
}

// Inexact Newton with corrections as poor as the forcing terms allow still reaches the tolerance,
// within two iterations of exact Newton, and asks for loose solves far from the answer.
TEST(Newton, InexactCorrectionsConvergeWithinTwoIterationsOfExactOnes)
{
  NewtonSettings settings;
  settings.residual_tolerance = 1e-12;
  ss::System exact_system(0.19);
  double     u_exact = 0, du = 0;
  const auto exact = newton_solve(exact_system, u_exact, du, settings);

  settings.forcing_max = 1e-2;
  ss::System system(0.19);
  system.inexact = true;
  double     u   = 0;
  const auto inexact = newton_solve(system, u, du, settings);
  EXPECT_NEAR(ss::force(u), 0.19, 1e-12 * 0.19);
  EXPECT_NEAR(u, u_exact, 1e-10);
  EXPECT_LE(inexact.iterations, exact.iterations + 2);
  ASSERT_FALSE(system.forcing_terms.empty());
  EXPECT_EQ(system.forcing_terms.front(), 1e-2);
  for (const double eta : system.forcing_terms)
    {
      EXPECT_LE(eta, 1e-2);
      EXPECT_GT(eta, 0.);
    }
}
