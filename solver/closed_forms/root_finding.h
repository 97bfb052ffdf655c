// Bracketed root finding for the closed forms that have no explicit inverse.
#ifndef CLOSED_FORMS_ROOT_FINDING_H
#define CLOSED_FORMS_ROOT_FINDING_H

#include <cmath>
#include <stdexcept>

namespace closed_forms
{
  namespace internal
  {
    // Bisection: slow but cannot leave the bracket, and the functions here are cheap.
    // Stops when the bracket no longer shrinks (machine precision) or is below abs_tolerance.
    template <typename Function>
    double
    find_root_by_bisection(const Function &f, double lower, double upper,
                           const double abs_tolerance = 0.0)
    {
      double f_lower = f(lower);
      const double f_upper = f(upper);
      if (f_lower == 0.0)
        return lower;
      if (f_upper == 0.0)
        return upper;
      if ((f_lower > 0.0) == (f_upper > 0.0))
        throw std::logic_error("closed_forms: root not bracketed (internal error)");
      for (unsigned int iteration = 0; iteration < 2000; ++iteration)
        {
          const double middle = 0.5 * (lower + upper);
          if (middle <= lower || middle >= upper || upper - lower <= abs_tolerance)
            break;
          const double f_middle = f(middle);
          if (f_middle == 0.0)
            return middle;
          if ((f_middle > 0.0) == (f_lower > 0.0))
            {
              lower = middle;
              f_lower = f_middle;
            }
          else
            upper = middle;
        }
      return 0.5 * (lower + upper);
    }
  } // namespace internal
} // namespace closed_forms

#endif
