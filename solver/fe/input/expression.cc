#include "input/expression.h"

#include <deal.II/base/function_parser.h>

#include "input/spec_list.h"

#include <iostream>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    // deal.II's FunctionParser prints muParser's diagnosis to std::cerr before it throws; the
    // caller's own message replaces it.
    struct SilencedErrorStream
    {
      std::ostringstream captured;
      std::streambuf    *previous = std::cerr.rdbuf(captured.rdbuf());
      ~SilencedErrorStream() { std::cerr.rdbuf(previous); }
    };
  } // namespace

  double evaluate_expression(const std::string                   &expression,
                             const std::map<std::string, double> &variables,
                             const std::string                   &where)
  {
    SilencedErrorStream silenced;
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
          message = message.substr(pos + 23);
        message = message.substr(0, message.find("Stacktrace"));
        // muParser's own words ("Unexpected token ... found at position ...") when it gave them
        const std::string printed = silenced.captured.str();
        const auto        said    = printed.find("Message:");
        if (said != std::string::npos)
          message = printed.substr(said + 8, printed.find('\n', said) - said - 8);
        message = trim(message.substr(0, 300));
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
