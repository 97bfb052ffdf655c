// The load-stepping path driver on springs with closed-form answers: the step schedule of an easy
// path, the stop just below a limit point with the state on the stable branch, the stability
// check's stop, interruption.
#include "nonlinear/load_stepping.h"

#include <gtest/gtest.h>

#include "softening_spring.h"

#include <vector>

using namespace compliant;
namespace ss = softening_spring;

namespace
{
  // The spring under lambda P, each step solved by the generic Newton from the current state.
  struct SpringPath : LoadPathProblem
  {
    double                 P, u = 0, lambda = 0, saved_u = 0, saved_lambda = 0;
    std::function<unsigned int(double)> negative_eigenvalues = [](double u) { return ss::stiffness(u) < 0 ? 1u : 0u; };
    std::function<bool()> stop = [] { return false; };
    std::vector<double>   accepted;

    explicit SpringPath(double P) : P(P) {}
    double       load_factor() const override { return lambda; }
    NewtonReport solve_to(double target) override
    {
      ss::System system(target * P);
      double     trial = u, du = 0;
      const auto report = newton_solve(system, trial, du, NewtonSettings{});
      u = trial, lambda = target;
      return report;
    }
    void         save_state() override { saved_u = u, saved_lambda = lambda; }
    void         restore_state() override { u = saved_u, lambda = saved_lambda; }
    double       change_from_saved_state() const override { return std::abs(u - saved_u); }
    unsigned int unstable_modes() override { return negative_eigenvalues(u); }
    bool         stop_requested() override { return stop(); }
  };

  LoadPathResult follow(SpringPath &path, const LoadSteppingSettings &settings = {})
  {
    return follow_load_path(path, settings, [&](const AcceptedStep &s) { path.accepted.push_back(s.load_factor); });
  }
} // namespace

// Far below the limit: steps 0.1, 0.15, 0.225, then the maximum 0.25, the last one cut to reach 1.
TEST(LoadStepping, EasyPathGrowsItsSteps)
{
  SpringPath path(0.1);
  const auto result = follow(path);
  EXPECT_TRUE(result.failure.empty()) << result.failure;
  EXPECT_EQ(result.cutbacks, 0u);
  const std::vector<double> expected{0.1, 0.25, 0.475, 0.725, 0.975, 1.0};
  ASSERT_EQ(path.accepted.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
    EXPECT_NEAR(path.accepted[k], expected[k], 1e-12);
  EXPECT_NEAR(ss::force(path.u), 0.1, 1e-10);
}

// P = 0.3 puts the limit point at lambda = 0.201003 / 0.3 = 0.67001: the path stops below it, no
// accepted state lies beyond it or on the far branch, and the stop is within a few minimum steps.
TEST(LoadStepping, StopsJustBelowALimitPoint)
{
  SpringPath            path(0.3);
  LoadSteppingSettings  settings;
  settings.minimum_step = 1e-4;
  const double          limit  = ss::limit_force() / 0.3;
  const auto            result = follow(path, settings);
  EXPECT_FALSE(result.failure.empty());
  EXPECT_NE(result.failure.find("Minimum step"), std::string::npos) << result.failure;
  EXPECT_GT(result.cutbacks, 0u);
  EXPECT_LE(path.lambda, limit);
  EXPECT_GT(path.lambda, limit - 1e-3);
  EXPECT_LT(path.u, ss::limit_displacement());
  for (const double l : path.accepted)
    EXPECT_LE(l, limit);
}

// A tangent that turns indefinite (a bifurcation the spring itself does not have, signalled at
// lambda > 0.5): the path stops at the step that passed it and names the last stable load.
TEST(LoadStepping, StabilityCheckStopsAtTheFirstUnstableState)
{
  SpringPath path(0.1);
  path.negative_eigenvalues = [&](double) { return path.lambda > 0.5 ? 2u : 0u; };
  const auto result = follow(path);
  EXPECT_NEAR(result.last_stable_load_factor, 0.475, 1e-12);
  EXPECT_NE(result.failure.find("2 negative eigenvalue(s)"), std::string::npos) << result.failure;
  EXPECT_NE(result.failure.find("prescribed displacement"), std::string::npos) << result.failure; // the advice
  EXPECT_NEAR(path.accepted.back(), 0.725, 1e-12); // the unstable step is still reported
}

TEST(LoadStepping, InterruptionKeepsTheConvergedSteps)
{
  SpringPath path(0.1);
  path.stop         = [&] { return path.accepted.size() >= 2; };
  const auto result = follow(path);
  EXPECT_TRUE(result.interrupted);
  EXPECT_EQ(result.steps, 2u);
  EXPECT_NEAR(path.lambda, 0.25, 1e-12);
}

namespace
{
  // A path given in closed form, u(lambda), no Newton: what the step control sees of a state.
  struct GivenPath : LoadPathProblem
  {
    std::function<double(double)> u;
    double                         lambda = 0, saved_lambda = 0;
    std::vector<double>            accepted;
    explicit GivenPath(std::function<double(double)> u) : u(std::move(u)) {}
    double       load_factor() const override { return lambda; }
    NewtonReport solve_to(double target) override
    {
      lambda = target;
      return {};
    }
    void         save_state() override { saved_lambda = lambda; }
    void         restore_state() override { lambda = saved_lambda; }
    double       change_from_saved_state() const override { return std::abs(u(lambda) - u(saved_lambda)); }
    unsigned int unstable_modes() override { return 0; }
  };
} // namespace

// A continuous path whose rate rises twentyfold at lambda = 0.5 (a kink, as where an imperfect
// beam turns into its buckled shape): beyond the kink every step, however small, changes the state
// many times faster than the last step accepted before it. Cutting back must be able to succeed (issue 27: the
// rate used to be compared with the last accepted step's only, so every smaller step failed too).
TEST(LoadStepping, FastButContinuousPathIsFollowed)
{
  GivenPath  path([](double l) { return l <= 0.5 ? l : 0.5 + 20 * (l - 0.5); });
  const auto result = follow_load_path(path, {}, [&](const AcceptedStep &s) { path.accepted.push_back(s.load_factor); });
  EXPECT_TRUE(result.failure.empty()) << result.failure;
  EXPECT_EQ(path.lambda, 1.0);
  EXPECT_GT(result.cutbacks, 0u);
}

// A path with a jump of 5 at lambda = 0.6 (another branch): never accepted; the path stops
// within the minimum step below it.
TEST(LoadStepping, JumpToAnotherBranchIsRefusedAtEveryStep)
{
  GivenPath            path([](double l) { return l + (l > 0.6 ? 5.0 : 0.0); });
  LoadSteppingSettings settings;
  settings.minimum_step = 1e-4;
  const auto result = follow_load_path(path, settings, [&](const AcceptedStep &s) { path.accepted.push_back(s.load_factor); });
  EXPECT_FALSE(result.failure.empty());
  EXPECT_NE(result.failure.find("jumped"), std::string::npos) << result.failure;
  EXPECT_LE(path.lambda, 0.6);
  EXPECT_GT(path.lambda, 0.6 - 2e-4);
}
