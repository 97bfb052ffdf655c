// Name-based registry: lookup and argument errors, defaults, warnings at the validity limits.
#include <closed_forms/beams.h>
#include <closed_forms/registry.h>
#include <closed_forms/torsion.h>

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <set>

using namespace closed_forms;

namespace
{
  // The invalid_argument message of f(), or "" when nothing is thrown.
  template <typename Function>
  std::string
  error_message(const Function &f)
  {
    try
      {
        f();
      }
    catch (const std::invalid_argument &error)
      {
        return error.what();
      }
    return "";
  }

  bool
  contains(const std::string &text, const std::string &part)
  {
    return text.find(part) != std::string::npos;
  }

  bool
  warns_about(const Result &result, const std::string &part)
  {
    for (const std::string &warning : result.warnings)
      if (contains(warning, part))
        return true;
    return false;
  }

  // A plausible value for every argument name used in the registry.
  const std::map<std::string, double> typical{
    {"P", 0.1},   {"M", 1.0},      {"T", 1.0},        {"L", 100.0},       {"l", 5.0},
    {"E", 2000.0}, {"nu", 0.35},   {"b", 3.0},        {"h", 1.5},         {"a", 4.0},
    {"rho", 1.2e-9}, {"n", 2.0},   {"kappa", 5.0 / 6.0}, {"gamma", 0.85}, {"K_theta", 2.65},
    {"Theta", 0.4}, {"link_length", 60.0}, {"r_i", 10.0}, {"r_o", 20.0}, {"r", 15.0}, {"K", 2.0}, {"t", 0.1}};
} // namespace

TEST(Registry, NamesAreUniqueSnakeCaseAndDocumented)
{
  std::set<std::string> names;
  const std::string text = documentation();
  for (const Formula &formula : registry())
    {
      EXPECT_TRUE(names.insert(formula.name).second) << formula.name;
      EXPECT_TRUE(std::regex_match(formula.name, std::regex("[a-z][a-z0-9_]*"))) << formula.name;
      EXPECT_FALSE(formula.source.empty()) << formula.name;
      EXPECT_TRUE(contains(text, "\n" + formula.name + "\n")) << formula.name;
      EXPECT_TRUE(contains(text, formula.source)) << formula.name;
    }
  for (const std::string expected :
       {"euler_bernoulli_cantilever_deflection", "timoshenko_cantilever_deflection",
        "euler_bernoulli_guided_stiffness", "timoshenko_guided_stiffness", "prbm_pivot_stiffness",
        "prbm_cantilever_force_stiffness", "saint_venant_beta", "saint_venant_alpha",
        "torsion_constant", "saint_venant_torsion_stiffness", "warping_constant",
        "vlasov_torsion_stiffness", "euler_bernoulli_cantilever_frequency", "euler_column_load",
        "engesser_column_load"})
    EXPECT_EQ(names.count(expected), 1u) << expected;
}

// Every formula evaluates with typical arguments to a finite value.
TEST(Registry, EveryFormulaEvaluates)
{
  for (const Formula &formula : registry())
    {
      std::map<std::string, double> args;
      for (const Argument &argument : formula.arguments)
        if (argument.required)
          args[argument.name] = typical.at(argument.name);
      const Result result = evaluate(formula.name, args);
      EXPECT_TRUE(std::isfinite(result.value)) << formula.name;
    }
}

TEST(Registry, UnknownFormulaNamesItAndListsKnownOnes)
{
  const std::string message = error_message([] { find("euler_cantilever"); });
  EXPECT_TRUE(contains(message, "'euler_cantilever'")) << message;
  EXPECT_TRUE(contains(message, "timoshenko_cantilever_deflection")) << message;
  EXPECT_TRUE(contains(error_message([] { evaluate("no_such_formula", {}); }), "no_such_formula"));
}

TEST(Registry, UnknownArgumentNamesItAndListsAcceptedOnes)
{
  const std::string message = error_message([] {
    evaluate("torsion_constant", {{"a", 2.0}, {"b", 1.0}, {"thickness", 1.0}});
  });
  EXPECT_TRUE(contains(message, "'thickness'")) << message;
  EXPECT_TRUE(contains(message, "accepted arguments: a, b")) << message;
}

TEST(Registry, MissingRequiredArgumentIsNamed)
{
  const std::string message =
    error_message([] { evaluate("euler_bernoulli_guided_stiffness", {{"L", 10.0}, {"E", 1.0}, {"b", 1.0}}); });
  EXPECT_TRUE(contains(message, "'h'")) << message;
}

TEST(Registry, NonPositiveLengthOrModulusIsRejected)
{
  for (const std::string name : {"L", "E", "b", "h"})
    {
      std::map<std::string, double> args{{"L", 10.0}, {"E", 1.0}, {"b", 1.0}, {"h", 1.0}};
      args[name] = (name == "E") ? 0.0 : -2.0;
      const std::string message =
        error_message([&] { evaluate("euler_bernoulli_guided_stiffness", args); });
      EXPECT_TRUE(contains(message, "'" + name + "'")) << message;
    }
  EXPECT_TRUE(contains(error_message([] {
                         evaluate("torsion_constant", {{"a", 2.0}, {"b", std::nan("")}});
                       }),
                       "'b'"));
  // Poisson's ratio may be negative (auxetic) but not reach -1 or 0.5.
  EXPECT_NO_THROW(evaluate("saint_venant_torsion_stiffness",
                           {{"a", 2.0}, {"b", 1.0}, {"L", 50.0}, {"E", 1.0}, {"nu", -0.2}}));
  EXPECT_TRUE(contains(error_message([] {
                         evaluate("saint_venant_torsion_stiffness",
                                  {{"a", 2.0}, {"b", 1.0}, {"L", 50.0}, {"E", 1.0}, {"nu", 0.5}});
                       }),
                       "'nu'"));
  EXPECT_TRUE(contains(error_message([] {
                         evaluate("euler_bernoulli_cantilever_frequency",
                                  {{"n", 1.5}, {"L", 50.0}, {"E", 1.0}, {"rho", 1.0}, {"b", 1.0}, {"h", 1.0}});
                       }),
                       "'n'"));
}

TEST(Registry, DefaultsAreFilledAndValuesMatchPlainFunctions)
{
  const std::map<std::string, double> args{{"L", 20.0}, {"E", 2000.0}, {"nu", 0.3}, {"b", 2.0}, {"h", 3.0}};
  EXPECT_DOUBLE_EQ(evaluate("timoshenko_guided_stiffness", args).value,
                   timoshenko_guided_stiffness(20.0, 2000.0, 0.3, 2.0, 3.0, 5.0 / 6.0));
  auto with_kappa = args;
  with_kappa["kappa"] = 0.85;
  EXPECT_DOUBLE_EQ(evaluate("timoshenko_guided_stiffness", with_kappa).value,
                   timoshenko_guided_stiffness(20.0, 2000.0, 0.3, 2.0, 3.0, 0.85));
  EXPECT_DOUBLE_EQ(evaluate("warping_constant", {{"a", 100.0}, {"b", 50.0}}).value,
                   warping_constant(100.0, 50.0));
  const Result deflection =
    evaluate("elastica_tip_force_deflection", {{"P", 1.0}, {"L", 1.0}, {"E", 12.0}, {"b", 1.0}, {"h", 1.0}});
  EXPECT_NEAR(deflection.value, 0.30172, 1e-5);  // alpha = 1, closed-forms.md table
}

// Each warning appears exactly when its limit is crossed.
TEST(Registry, WarningsAppearExactlyOutsideTheValidityRange)
{
  const auto cantilever = [](const double L, const double P) {
    return evaluate("euler_bernoulli_cantilever_deflection",
                    {{"P", P}, {"L", L}, {"E", 2000.0}, {"b", 1.0}, {"h", 1.0}});
  };
  EXPECT_TRUE(cantilever(10.1, 1e-3).warnings.empty());
  EXPECT_TRUE(warns_about(cantilever(9.9, 1e-3), "L/h"));
  EXPECT_EQ(cantilever(9.9, 1e-3).warnings.size(), 1u);
  // v/L = P L^2 / (3 E I) = 0.1 at P = 0.3 E I / L^2 = 0.3 * 2000/12 / 400 = 0.125 for L = 20.
  EXPECT_TRUE(cantilever(20.0, 0.124).warnings.empty());
  EXPECT_TRUE(warns_about(cantilever(20.0, 0.126), "nonlinearity"));
  EXPECT_TRUE(warns_about(cantilever(20.0, -0.126), "nonlinearity"));

  const auto guided = [](const double L) {
    return evaluate("euler_bernoulli_guided_stiffness", {{"L", L}, {"E", 1.0}, {"b", 1.0}, {"h", 2.0}});
  };
  EXPECT_TRUE(guided(20.1).warnings.empty());
  EXPECT_TRUE(warns_about(guided(19.9), "L/h"));
  const auto timoshenko = [](const double L) {
    return evaluate("timoshenko_guided_stiffness",
                    {{"L", L}, {"E", 1.0}, {"nu", 0.3}, {"b", 1.0}, {"h", 2.0}});
  };
  EXPECT_TRUE(timoshenko(4.1).warnings.empty());
  EXPECT_TRUE(warns_about(timoshenko(3.9), "L/h"));

  const auto pivot = [](const std::map<std::string, double> &extra) {
    std::map<std::string, double> args{{"E", 1.0}, {"b", 1.0}, {"h", 0.5}, {"l", 10.0}};
    for (const auto &[name, value] : extra)
      args[name] = value;
    return evaluate("prbm_pivot_stiffness", args);
  };
  EXPECT_TRUE(pivot({}).warnings.empty());
  EXPECT_TRUE(pivot({{"link_length", 101.0}}).warnings.empty());
  EXPECT_TRUE(warns_about(pivot({{"link_length", 99.0}}), "l/link_length"));
  EXPECT_TRUE(warns_about(pivot({{"h", 1.01}}), "l/h"));
  EXPECT_TRUE(warns_about(pivot({{"h", 1.01}}), "092302"));

  const auto tip_y = [](const double degrees) {
    return evaluate("prbm_cantilever_tip_y", {{"l", 1.0}, {"Theta", degrees * M_PI / 180.0}});
  };
  EXPECT_TRUE(tip_y(63.9).warnings.empty());
  EXPECT_TRUE(tip_y(-63.9).warnings.empty());
  EXPECT_TRUE(warns_about(tip_y(64.1), "64 deg"));
  EXPECT_TRUE(warns_about(tip_y(-64.1), "64 deg"));

  // Sides in either order: the longer one (a = 4) sets the limit L = 40.
  const auto saint_venant = [](const double L) {
    return evaluate("saint_venant_torsion_stiffness",
                    {{"a", 0.5}, {"b", 4.0}, {"L", L}, {"E", 1.0}, {"nu", 0.3}});
  };
  EXPECT_TRUE(saint_venant(40.1).warnings.empty());
  EXPECT_TRUE(warns_about(saint_venant(39.9), "Saint-Venant assumes free warping; bar shorter than ten widths"));
  const auto vlasov = [](const double L) {
    return evaluate("vlasov_torsion_stiffness", {{"a", 0.5}, {"b", 4.0}, {"L", L}, {"E", 1.0}, {"nu", 0.3}});
  };
  EXPECT_TRUE(vlasov(4.1).warnings.empty());
  EXPECT_TRUE(warns_about(vlasov(3.9), "L/a"));

  // Mode n: (L/h) beta_1/beta_n >= 10. Mode 2: L/h >= 10 * 4.69409/1.87510 = 25.034.
  const auto frequency = [](const double n, const double L) {
    return evaluate("euler_bernoulli_cantilever_frequency",
                    {{"n", n}, {"L", L}, {"E", 1.0}, {"rho", 1.0}, {"b", 1.0}, {"h", 1.0}});
  };
  EXPECT_TRUE(frequency(1, 10.1).warnings.empty());
  EXPECT_TRUE(warns_about(frequency(1, 9.9), "shear and rotary inertia"));
  EXPECT_TRUE(frequency(2, 25.1).warnings.empty());
  EXPECT_TRUE(warns_about(frequency(2, 24.9), "shear and rotary inertia"));

  // End moment: strain t h / (2 L) = 1 % at t = 0.2 for L/h = 10 ... use L/h = 100: t = 2.
  const auto roll_up = [](const double t) {
    // E I = 1/12 with b = h = 1; M = t E I / L.
    return evaluate("elastica_end_moment_deflection",
                    {{"M", t / 12.0 / 100.0}, {"L", 100.0}, {"E", 1.0}, {"b", 1.0}, {"h", 1.0}});
  };
  EXPECT_TRUE(roll_up(1.99).warnings.empty());
  EXPECT_TRUE(warns_about(roll_up(2.01), "strain"));
  EXPECT_FALSE(warns_about(roll_up(6.28), "2 pi"));
  EXPECT_TRUE(warns_about(roll_up(6.29), "2 pi"));
}

// Qiu-Lang-Slocum's estimates hold for a shallow beam of large Q = h/t: warnings below Q = 10,
// a different one where it is not bistable at all (Q <= 2.31), and for h/L > 0.1.
TEST(Registry, BistableEstimatesWarnOutsideLargeQShallowBeams)
{
  const auto top = [](const double L, const double t, const double h) {
    return evaluate("bistable_switching_force_top", {{"L", L}, {"E", 1000.0}, {"b", 1.0}, {"t", t}, {"h", h}});
  };
  EXPECT_TRUE(top(800, 1, 16).warnings.empty());
  EXPECT_TRUE(warns_about(top(400, 1, 8), "large-Q"));
  EXPECT_TRUE(warns_about(top(400, 1, 2), "not bistable"));
  EXPECT_FALSE(warns_about(top(400, 1, 2), "large-Q"));
  EXPECT_TRUE(warns_about(top(100, 1, 12), "shallow"));
  // Per beam, in E I h / L^3: 740 forward, 370 back (the paper's coefficients).
  const double unit = 1000.0 / 12.0 * 16 / (800.0 * 800.0 * 800.0);
  EXPECT_NEAR(top(800, 1, 16).value / unit, 740.0, 1e-9);
  EXPECT_NEAR(evaluate("bistable_switching_force_bottom", {{"L", 800.0}, {"E", 1000.0}, {"b", 1.0}, {"t", 1.0}, {"h", 16.0}}).value / unit,
              370.0, 1e-9);
}

TEST(Registry, WarningFreeFormulasStayQuiet)
{
  EXPECT_TRUE(evaluate("saint_venant_beta", {{"a", 1000.0}, {"b", 1.0}}).warnings.empty());
  EXPECT_TRUE(evaluate("warping_constant", {{"a", 1.0}, {"b", 1.0}}).warnings.empty());
}

// The error bounds of the cantilever formulas (model ladder, rung (a)) must cover what they
// claim to: Euler-Bernoulli's departure from the exact Timoshenko-Goodier elasticity solution
// (shear) at any nu, and Timoshenko's; and they grow with h/L and with the load (elastica).
TEST(Registry, CantileverBoundsCoverTheShearTheyOmit)
{
  for (const double nu : {0.0, 0.3, 0.49})
    for (const double slenderness : {5.0, 10.0, 40.0})
      {
        const std::map<std::string, double> beam{{"P", 1e-3}, {"L", slenderness}, {"E", 1000},
                                                 {"b", 1}, {"h", 1}};
        auto with_nu = beam;
        with_nu["nu"] = nu;
        const auto exact = closed_forms::evaluate("timoshenko_goodier_cantilever_deflection", with_nu);
        const auto euler = closed_forms::evaluate("euler_bernoulli_cantilever_deflection", beam);
        const auto timo  = closed_forms::evaluate("timoshenko_cantilever_deflection", with_nu);
        EXPECT_GE(euler.error_bound, std::abs(euler.value / exact.value - 1));
        EXPECT_GE(timo.error_bound, std::abs(timo.value / exact.value - 1));
        // the root-restraint allowance (h/L)^2 is part of every bound
        EXPECT_GE(exact.error_bound, 1 / (slenderness * slenderness));
        EXPECT_EQ(euler.bound_models, std::vector<std::string>{"plane stress"});
      }
  // A large load adds the elastica's geometric term: alpha = 1 is 4.8 % off the linear answer.
  const auto heavy = closed_forms::evaluate(
    "euler_bernoulli_cantilever_deflection", {{"P", 1000.0 / 12 / 1e4}, {"L", 100}, {"E", 1000}, {"b", 1}, {"h", 1}});
  EXPECT_GT(heavy.error_bound, 0.04);
  // Formulas without a bound say so with NaN.
  EXPECT_TRUE(std::isnan(closed_forms::evaluate("torsion_constant", {{"a", 1}, {"b", 2}}).error_bound));
}
