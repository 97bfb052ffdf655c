#include "quantities/comparison.h"

#include <closed_forms/registry.h>

#include "input/spec_list.h"

#include <cmath>
#include <stdexcept>

namespace compliant
{
  std::vector<CheckRequest> parse_checks(const std::string &text)
  {
    const std::string         where = "Comparison/Checks";
    std::vector<CheckRequest> requests;
    for (const auto &entry : split(text, ';'))
      {
        if (entry.empty())
          continue;
        const auto tilde = entry.find('~');
        const auto open  = entry.find('(', tilde);
        const auto close = entry.rfind(')');
        if (tilde == std::string::npos || open == std::string::npos || close < open)
          throw std::invalid_argument(where + ": expected 'quantity ~ formula(arg=expr, ...)', got '" +
                                      entry + "'");
        CheckRequest r;
        r.quantity = trim(entry.substr(0, tilde));
        r.formula  = trim(entry.substr(tilde + 1, open - tilde - 1));
        try
          {
            const auto &formula = closed_forms::find(r.formula);
            for (const auto &arg : split(entry.substr(open + 1, close - open - 1), ','))
              {
                if (arg.empty())
                  continue;
                const auto eq = arg.find('=');
                if (eq == std::string::npos)
                  throw std::invalid_argument("argument '" + arg + "' is not 'name=expression'");
                const auto name = trim(arg.substr(0, eq));
                bool       known = false;
                for (const auto &a : formula.arguments)
                  known = known || a.name == name;
                if (!known)
                  {
                    std::string accepted;
                    for (const auto &a : formula.arguments)
                      accepted += " " + a.name;
                    throw std::invalid_argument("'" + r.formula + "' has no argument '" + name +
                                                "'; it accepts:" + accepted);
                  }
                r.arguments[name] = trim(arg.substr(eq + 1));
              }
          }
        catch (const std::invalid_argument &e)
          {
            throw std::invalid_argument(where + ": " + e.what());
          }
        requests.push_back(r);
      }
    return requests;
  }

  void add_derived_quantities(const std::string &text, std::map<std::string, double> &quantities,
                              const std::map<std::string, double> &variables)
  {
    for (const auto &entry : split(text, ';'))
      {
        if (entry.empty())
          continue;
        const auto eq = entry.find('=');
        if (eq == std::string::npos)
          throw std::invalid_argument("Quantities/Derived: expected 'name = expression', got '" +
                                      entry + "'");
        auto all = variables;
        for (const auto &q : quantities)
          all[q.first] = q.second;
        const auto name  = trim(entry.substr(0, eq));
        quantities[name] = evaluate_expression(trim(entry.substr(eq + 1)), all,
                                               "Quantities/Derived '" + name + "'");
      }
  }

  std::vector<Comparison> run_checks(const std::vector<CheckRequest>     &requests,
                                     const std::map<std::string, double> &quantities,
                                     const std::map<std::string, double> &variables)
  {
    auto all = variables;
    for (const auto &q : quantities)
      all[q.first] = q.second;
    std::vector<Comparison> comparisons;
    for (const auto &r : requests)
      {
        const std::string where = "Comparison/Checks '" + r.quantity + " ~ " + r.formula + "'";
        const auto        it    = quantities.find(r.quantity);
        if (it == quantities.end())
          {
            std::string known;
            for (const auto &q : quantities)
              known += " " + q.first;
            throw std::invalid_argument(where + ": no quantity '" + r.quantity +
                                        "'; this run computes:" + known);
          }
        std::map<std::string, double> arguments;
        for (const auto &[name, expression] : r.arguments)
          arguments[name] = evaluate_expression(expression, all, where + ", argument " + name);
        closed_forms::Result result;
        try
          {
            result = closed_forms::evaluate(r.formula, arguments);
          }
        catch (const std::exception &e)
          {
            throw std::invalid_argument(where + ": " + e.what());
          }
        Comparison c;
        c.quantity            = r.quantity;
        c.formula             = r.formula;
        c.computed            = it->second;
        c.reference           = result.value;
        c.relative_difference = (c.computed - c.reference) / std::abs(c.reference);
        c.warnings            = result.warnings;
        comparisons.push_back(c);
      }
    return comparisons;
  }
} // namespace compliant
