// Discretization error of a quantity of interest from a sequence of refined solutions (Richardson
// extrapolation with the observed order). With Q_k = Q + C h_k^p, three solutions give p from
// (Q_k - Q_(k-1)) / (Q_(k-1) - Q_(k-2)) = (h_k^p - h_(k-1)^p) / (h_(k-1)^p - h_(k-2)^p), and the
// error left in Q_k is (Q_k - Q_(k-1)) h_k^p / (h_(k-1)^p - h_k^p). Uniform refinement halves h;
// adaptive refinement gives any decreasing h (the caller uses h = N^(-1/dim) from the DoF counts).
// With only two solutions the order is assumed; when the differences do not shrink at least like
// h^0.5 (a stress singularity, a peak at a re-entrant corner) there is no converged value and no
// estimate.
#pragma once

#include <string>
#include <vector>

namespace compliant
{
  struct ErrorEstimate
  {
    bool        available = false; // false: too few rungs or irregular convergence
    double      absolute  = 0;     // |Q_exact - Q_k| estimated
    double      relative  = 0;     // absolute / |Q_k|
    double      observed_order = 0; // p in h^p (assumed when only two values exist)
    bool        order_observed = false;
    std::string note;               // why there is no estimate, or that the order was assumed
  };

  // values: Q on successive refinements, last the finest; sizes: the mesh size h of each (any
  // unit, strictly decreasing); assumed_order: the order used when only two values exist.
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values,
                                              const std::vector<double> &sizes, double assumed_order);

  // Uniform refinement: h halves from one value to the next.
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values, double assumed_order);
} // namespace compliant
