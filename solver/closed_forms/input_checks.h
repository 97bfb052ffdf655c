// Argument checks shared by the closed-form functions: bad input throws std::invalid_argument
// naming the parameter and what was expected.
#ifndef CLOSED_FORMS_INPUT_CHECKS_H
#define CLOSED_FORMS_INPUT_CHECKS_H

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace closed_forms
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

    inline void
    require_finite(const char *name, const double value)
    {
      if (!std::isfinite(value))
        throw std::invalid_argument(std::string("closed_forms: parameter '") + name +
                                    "' must be a finite number, got " + format_number(value));
    }

    // Lengths, moduli and densities.
    inline void
    require_positive(const char *name, const double value)
    {
      if (!(std::isfinite(value) && value > 0.0))
        throw std::invalid_argument(std::string("closed_forms: parameter '") + name +
                                    "' must be positive and finite, got " + format_number(value));
    }

    // Isotropic stability bounds for Poisson's ratio.
    inline void
    require_poisson_ratio(const char *name, const double value)
    {
      if (!(std::isfinite(value) && value > -1.0 && value < 0.5))
        throw std::invalid_argument(std::string("closed_forms: parameter '") + name +
                                    "' (Poisson's ratio) must lie in (-1, 0.5), got " +
                                    format_number(value));
    }
  } // namespace internal
} // namespace closed_forms

#endif
