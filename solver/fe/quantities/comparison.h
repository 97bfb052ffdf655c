// Derived quantities (muparser expressions of other quantities) and the comparison of quantities
// with the named closed forms of the closed_forms library, with their validity warnings.
#pragma once

#include "input/expression.h"

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct Comparison
  {
    std::string              quantity;
    std::string              formula;
    double                   computed            = 0;
    double                   reference           = 0;
    double                   relative_difference = 0; // (computed - reference) / |reference|
    std::vector<std::string> warnings;
  };

  struct CheckRequest
  {
    std::string                        quantity;
    std::string                        formula;
    std::map<std::string, std::string> arguments; // name -> expression
  };

  // Parses 'qoi ~ formula(a=expr, b=expr); ...' and checks formula and argument names against the
  // closed-form registry. Throws std::invalid_argument naming Comparison/Checks.
  std::vector<CheckRequest> parse_checks(const std::string &text);

  // Evaluates 'name = expression; ...' in order, each result available to the next.
  void add_derived_quantities(const std::string &text, std::map<std::string, double> &quantities,
                              const std::map<std::string, double> &variables);

  std::vector<Comparison> run_checks(const std::vector<CheckRequest>     &requests,
                                     const std::map<std::string, double> &quantities,
                                     const std::map<std::string, double> &variables);
} // namespace compliant
