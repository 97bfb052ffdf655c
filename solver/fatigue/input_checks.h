// Argument checks shared by the fatigue functions: bad input throws std::invalid_argument naming
// the parameter and what was expected.
#ifndef FATIGUE_INPUT_CHECKS_H
#define FATIGUE_INPUT_CHECKS_H

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fatigue
{
  namespace internal
  {
    inline std::string
    format_number(const double value)
    {
      std::ostringstream out;
      out.precision(17);
      out << value;
      return out.str();
    }

    [[noreturn]] inline void
    fail(const std::string &parameter, const std::string &expected, const double value)
    {
      throw std::invalid_argument("fatigue: parameter '" + parameter + "' must be " + expected +
                                  ", got " + format_number(value));
    }

    inline void
    require_finite(const std::string &parameter, const double value)
    {
      if (!std::isfinite(value))
        fail(parameter, "a finite number", value);
    }

    inline void
    require_positive(const std::string &parameter, const double value)
    {
      if (!(std::isfinite(value) && value > 0.0))
        fail(parameter, "positive and finite", value);
    }

    inline void
    require_non_negative(const std::string &parameter, const double value)
    {
      if (!(std::isfinite(value) && value >= 0.0))
        fail(parameter, "non-negative and finite", value);
    }
  } // namespace internal
} // namespace fatigue

#endif
