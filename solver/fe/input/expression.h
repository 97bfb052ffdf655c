// Evaluation of muparser expressions over named values (geometry parameters, material constants,
// quantities), used wherever a case file may write a formula instead of a number.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  // Throws std::invalid_argument naming `where`, the expression and the known names.
  double evaluate_expression(const std::string                   &expression,
                             const std::map<std::string, double> &variables,
                             const std::string                   &where);

  // Space-separated coordinates, each a number or an expression ("l/2 0").
  std::vector<double> evaluate_coordinates(const std::string                   &text,
                                           const std::map<std::string, double> &variables,
                                           const std::string                   &where);
} // namespace compliant
