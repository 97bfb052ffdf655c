#include "registry.h"

#include "formula_table.h"
#include "input_checks.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace closed_forms
{
  namespace
  {
    std::string
    known_names()
    {
      std::string names;
      for (const Formula &formula : registry())
        names += (names.empty() ? "" : ", ") + formula.name;
      return names;
    }

    std::string
    accepted_arguments(const Formula &formula)
    {
      std::string names;
      for (const Argument &argument : formula.arguments)
        names += (names.empty() ? "" : ", ") + argument.name;
      return names;
    }
  } // namespace

  const std::vector<Formula> &
  registry()
  {
    static const std::vector<Formula> table = internal::make_formula_table();
    return table;
  }

  const Formula &
  find(const std::string &name)
  {
    for (const Formula &formula : registry())
      if (formula.name == name)
        return formula;
    throw std::invalid_argument("closed_forms: unknown formula '" + name + "'; known formulas: " +
                                known_names());
  }

  Result
  evaluate(const std::string &name, const std::map<std::string, double> &args)
  {
    const Formula &formula = find(name);
    for (const auto &[given_name, value] : args)
      {
        bool accepted = false;
        for (const Argument &argument : formula.arguments)
          accepted = accepted || argument.name == given_name;
        if (!accepted)
          throw std::invalid_argument("closed_forms: formula '" + name + "' has no argument '" +
                                      given_name + "'; accepted arguments: " +
                                      accepted_arguments(formula));
        if (!std::isfinite(value))
          throw std::invalid_argument("closed_forms: formula '" + name + "': argument '" + given_name +
                                      "' must be finite, got " + internal::format_number(value));
      }

    std::map<std::string, double> complete;
    for (const Argument &argument : formula.arguments)
      {
        const auto given = args.find(argument.name);
        if (given == args.end())
          {
            if (argument.required)
              throw std::invalid_argument("closed_forms: formula '" + name +
                                          "' needs argument '" + argument.name + "' (" +
                                          argument.description + ")");
            complete[argument.name] = argument.default_value;
            continue;
          }
        if (argument.must_be_positive && !(given->second > 0.0))
          throw std::invalid_argument("closed_forms: formula '" + name + "': argument '" +
                                      argument.name + "' (" + argument.description +
                                      ") must be positive, got " +
                                      internal::format_number(given->second));
        complete[argument.name] = given->second;
      }
    return formula.evaluate(complete);
  }

  std::string
  documentation()
  {
    std::ostringstream out;
    out << "Closed-form reference formulas (rectangular section: b width, h depth in the bending "
           "direction, I = b h^3/12, A = b h; G = E/(2(1+nu)); any consistent units; angles in rad)\n";
    for (const Formula &formula : registry())
      {
        out << "\n" << formula.name << "\n  " << formula.description << "\n  source: " << formula.source
            << "\n";
        for (const Argument &argument : formula.arguments)
          {
            out << "    " << argument.name << ": " << argument.description;
            if (argument.required)
              out << " (required)";
            else if (std::isnan(argument.default_value))
              out << " (optional)";
            else
              out << " (default " << argument.default_value << ")";
            out << "\n";
          }
      }
    return out.str();
  }
} // namespace closed_forms
