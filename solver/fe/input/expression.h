// Evaluation of muparser expressions over named values (geometry parameters, material constants,
// quantities), used wherever a case file may write a formula instead of a number.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim>
  class FunctionParser;
}

namespace compliant
{
  // Throws std::invalid_argument naming `where`, the expression and the known names.
  double evaluate_expression(const std::string                   &expression,
                             const std::map<std::string, double> &variables,
                             const std::string                   &where);

  // One expression of x, y (, z) and the named constants per component, as a deal.II function
  // (loads, prescribed motions). Evaluated once at the origin, since muparser finds syntax errors
  // only on evaluation: a malformed expression throws std::invalid_argument here, "<where>: cannot
  // evaluate '<expressions>' (<muparser's diagnosis, with the position>); use ...", and the
  // library's own text is not printed.
  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>> make_field_function(const std::vector<std::string>     &expressions,
                                                                   const std::map<std::string, double> &constants,
                                                                   const std::string                   &where);

  // Space-separated coordinates, each a number or an expression ("l/2 0").
  std::vector<double> evaluate_coordinates(const std::string                   &text,
                                           const std::map<std::string, double> &variables,
                                           const std::string                   &where);
} // namespace compliant
