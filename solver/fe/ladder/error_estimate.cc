#include "ladder/error_estimate.h"

#include <cmath>

namespace compliant
{
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values, const double assumed_order)
  {
    ErrorEstimate e;
    const std::size_t n = values.size();
    if (n < 2)
      {
        e.note = "one solution: no estimate yet";
        return e;
      }
    const double q     = values[n - 1];
    const double d     = std::abs(values[n - 1] - values[n - 2]);
    const double scale = std::max(std::abs(q), 1e-300);
    double       ratio;
    if (n == 2)
      {
        ratio = std::pow(2.0, -assumed_order);
        e.note = "order assumed (" + std::to_string(assumed_order).substr(0, 4) + ")";
        e.observed_order = assumed_order;
      }
    else
      {
        const double d_previous = std::abs(values[n - 2] - values[n - 3]);
        if (d <= 1e-14 * scale) // converged to round-off
          {
            e.available = true, e.absolute = d, e.relative = d / scale, e.observed_order = 99;
            e.order_observed = true;
            return e;
          }
        ratio = d_previous > 0 ? d / d_previous : 2;
        // Irregular: the differences grow, or shrink slower than first order (2^-0.5): a singular
        // quantity (peak stress at a sharp corner) has no converged value to estimate.
        if (!(ratio < std::pow(2.0, -0.5)))
          {
            e.note = "irregular convergence (difference ratio " + std::to_string(ratio).substr(0, 5) +
                     "): no converged value, no estimate";
            return e;
          }
        e.observed_order = -std::log2(ratio);
        e.order_observed = true;
      }
    e.available = true;
    e.absolute  = d * ratio / (1 - ratio);
    e.relative  = e.absolute / scale;
    return e;
  }
} // namespace compliant
