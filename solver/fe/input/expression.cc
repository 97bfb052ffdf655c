#include "input/expression.h"

#include <deal.II/base/function_parser.h>

#include "input/spec_list.h"

#include <sstream>
#include <stdexcept>

namespace compliant
{
  double evaluate_expression(const std::string                   &expression,
                             const std::map<std::string, double> &variables,
                             const std::string                   &where)
  {
    try
      {
        dealii::FunctionParser<1> parser(1);
        parser.initialize("x_", expression, variables);
        return parser.value(dealii::Point<1>());
      }
    catch (const std::exception &e)
      {
        std::string known;
        for (const auto &v : variables)
          known += " " + v.first;
        std::string message = e.what();
        const auto  pos     = message.find("Additional information:");
        if (pos != std::string::npos)
          message = trim(message.substr(pos + 23, 300));
        throw std::invalid_argument(where + ": cannot evaluate '" + expression + "' (" + message +
                                    "); known names:" + known);
      }
  }

  std::vector<double> evaluate_coordinates(const std::string                   &text,
                                           const std::map<std::string, double> &variables,
                                           const std::string                   &where)
  {
    std::istringstream  in(text);
    std::vector<double> values;
    std::string         token;
    while (in >> token)
      values.push_back(evaluate_expression(token, variables, where));
    return values;
  }
} // namespace compliant
