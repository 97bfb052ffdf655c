#include "input/expression.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/lac/vector.h>

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

    // muParser's own words ("Unexpected end of expression at position 6") when it gave them,
    // else deal.II's message without its boilerplate.
    std::string diagnosis(const std::exception &e, const SilencedErrorStream &silenced)
    {
      std::string message = e.what();
      const auto  pos     = message.find("Additional information:");
      if (pos != std::string::npos)
        message = message.substr(pos + 23);
      message = message.substr(0, message.find("Stacktrace"));
      const std::string printed = silenced.captured.str();
      const auto        said    = printed.find("Message:");
      if (said != std::string::npos)
        {
          message = printed.substr(said + 8, printed.find('\n', said) - said - 8);
          // "<Unexpected end of expression at position 6>": the brackets are muParser's
          message = trim(message);
          if (message.size() > 1 && message.front() == '<' && message.back() == '>')
            message = message.substr(1, message.size() - 2);
        }
      return trim(message.substr(0, 300));
    }
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
        throw std::invalid_argument(where + ": cannot evaluate '" + expression + "' (" +
                                    diagnosis(e, silenced) + "); known names:" + known);
      }
  }

  template <int dim>
  std::unique_ptr<dealii::FunctionParser<dim>> make_field_function(const std::vector<std::string>     &expressions,
                                                                   const std::map<std::string, double> &constants,
                                                                   const std::string                   &where)
  {
    SilencedErrorStream silenced;
    auto                function = std::make_unique<dealii::FunctionParser<dim>>(expressions.size());
    try
      {
        function->initialize(dim == 2 ? "x,y" : "x,y,z", expressions, constants);
        dealii::Vector<double> probe(expressions.size());
        function->vector_value(dealii::Point<dim>(), probe);
      }
    catch (const std::exception &e)
      {
        std::string text;
        for (const auto &expression : expressions)
          text += (text.empty() ? "" : " ") + expression;
        throw std::invalid_argument(where + ": cannot evaluate '" + text + "' (" + diagnosis(e, silenced) +
                                    "); use numbers, x, y" + (dim == 3 ? ", z" : "") +
                                    " and the geometry parameters");
      }
    return function;
  }

  template std::unique_ptr<dealii::FunctionParser<2>>
  make_field_function<2>(const std::vector<std::string> &, const std::map<std::string, double> &, const std::string &);
  template std::unique_ptr<dealii::FunctionParser<3>>
  make_field_function<3>(const std::vector<std::string> &, const std::map<std::string, double> &, const std::string &);

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
