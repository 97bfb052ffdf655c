#include "ladder/error_estimate.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    // Ratio of successive differences the model Q = Q* + C h^p predicts.
    double predicted_ratio(const double h0, const double h1, const double h2, const double p)
    {
      return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h0, p) - std::pow(h1, p));
    }

    std::string short_number(const double x)
    {
      char text[32];
      std::snprintf(text, sizeof text, "%.3g", x);
      return text;
    }
  } // namespace

  ErrorEstimate estimate_discretization_error(const std::vector<double> &values,
                                              const std::vector<double> &sizes, const double assumed_order,
                                              const double attainable)
  {
    if (sizes.size() != values.size())
      throw std::invalid_argument("estimate_discretization_error: one mesh size per value");
    for (std::size_t k = 1; k < sizes.size(); ++k)
      if (!(sizes[k] < sizes[k - 1]) || !(sizes[k] > 0))
        throw std::invalid_argument("estimate_discretization_error: mesh sizes must decrease");
    ErrorEstimate e;
    const std::size_t n = values.size();
    if (n < 2)
      {
        e.note = "one solution: no estimate yet";
        return e;
      }
    const double q     = values[n - 1];
    const double d     = values[n - 1] - values[n - 2];
    const double scale = std::max(std::abs(q), 1e-300);
    double       p     = assumed_order;
    if (n == 2)
      e.note = "order assumed (" + std::to_string(assumed_order).substr(0, 4) + ")";
    else
      {
        const double d_previous = values[n - 2] - values[n - 3];
        if (std::abs(d) <= 1e-14 * scale) // converged to round-off
          {
            e.available = true, e.absolute = std::abs(d), e.relative = e.absolute / scale;
            e.observed_order = 99, e.order_observed = true;
            return e;
          }
        if (d * d_previous < 0)
          {
            e.note = "successive differences change sign (" + short_number(d_previous) + ", " + short_number(d) +
                     "): not monotone, no trusted estimate";
            return e;
          }
        const double h0 = 1, h1 = sizes[n - 2] / sizes[n - 3], h2 = sizes[n - 1] / sizes[n - 3];
        const double ratio = d_previous != 0 ? std::abs(d / d_previous) : 2;
        // Irregular: the differences grow or shrink slower than h^0.5: a singular quantity (peak
        // stress at a sharp corner) has no converged value to estimate.
        if (!(ratio < predicted_ratio(h0, h1, h2, 0.5)))
          {
            e.note = "irregular convergence (difference ratio " + std::to_string(ratio).substr(0, 5) +
                     "): no converged value, no estimate";
            return e;
          }
        // predicted_ratio falls monotonically in p: bisect.
        double low = 0.5, high = 20;
        for (int i = 0; i < 200 && predicted_ratio(h0, h1, h2, high) > ratio; ++i)
          high *= 2;
        for (int i = 0; i < 200; ++i)
          {
            const double mid = 0.5 * (low + high);
            (predicted_ratio(h0, h1, h2, mid) > ratio ? low : high) = mid;
          }
        p                = 0.5 * (low + high);
        e.order_observed = true;
        if (attainable > 0 && p > attainable)
          {
            e.observed_order = p;
            e.note = "observed order " + short_number(p) + " above the attainable " + short_number(attainable) +
                     ": a coincidence of pre-asymptotic errors, no trusted estimate";
            return e;
          }
      }
    e.observed_order = p;
    e.available      = true;
    e.absolute       = std::abs(d) / (std::pow(sizes[n - 2] / sizes[n - 1], p) - 1);
    e.relative       = e.absolute / scale;
    return e;
  }

  ErrorEstimate estimate_discretization_error(const std::vector<double> &values, const double assumed_order,
                                              const double attainable)
  {
    std::vector<double> sizes(values.size());
    for (std::size_t k = 0; k < sizes.size(); ++k)
      sizes[k] = std::ldexp(1.0, -static_cast<int>(k));
    return estimate_discretization_error(values, sizes, assumed_order, attainable);
  }
} // namespace compliant
