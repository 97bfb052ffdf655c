// Name-based access to the closed forms, so that a case file can name a reference formula and give
// its arguments as name=value pairs. Plain functions live in beams.h, prbm.h, torsion.h, elastica.h.
#ifndef CLOSED_FORMS_REGISTRY_H
#define CLOSED_FORMS_REGISTRY_H

#include <functional>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace closed_forms
{
  struct Argument
  {
    std::string name;
    std::string description;
    bool required;
    double default_value;  // NaN for an optional argument that has no default ("not given")
    bool must_be_positive = false;  // lengths, moduli, densities: evaluate() rejects values <= 0
  };

  struct Result
  {
    Result(double value = 0, std::vector<std::string> warnings = {})
      : value(value), warnings(std::move(warnings))
    {}
    double value;
    std::vector<std::string> warnings;  // the arguments lie outside the formula's validity range
    // Where the formula can bound its own error: a bound on |value / elasticity solution - 1|, what
    // it is made of, and the models (Model = ...) the bound holds for. NaN: no bound.
    double error_bound = std::numeric_limits<double>::quiet_NaN();
    std::string error_bound_basis;
    std::vector<std::string> bound_models;
  };

  struct Formula
  {
    std::string name;         // snake_case
    std::string description;  // what is returned, in consistent units
    std::string source;       // citation
    std::vector<Argument> arguments;
    // Receives every argument, defaults filled in.
    std::function<Result(const std::map<std::string, double> &)> evaluate;
  };

  const std::vector<Formula> &registry();

  // Throws std::invalid_argument listing the known names.
  const Formula &find(const std::string &name);

  // Validates the arguments (unknown name, missing required argument, non-finite value, non-positive
  // length or modulus: std::invalid_argument naming the argument), fills defaults, evaluates.
  Result evaluate(const std::string &name, const std::map<std::string, double> &args);

  // Human-readable list of all formulas with their arguments and sources.
  std::string documentation();
} // namespace closed_forms

#endif
