// Discretization error of a quantity of interest from a sequence of uniformly refined solutions
// (Richardson extrapolation with the observed order): for differences d_k = |Q_k - Q_(k-1)| that
// shrink by a steady ratio r = d_k / d_(k-1) = 2^-p, the error left in Q_k is d_k r / (1 - r).
// With only two solutions the order is assumed; when the differences do not shrink (a stress
// singularity, a peak at a re-entrant corner) there is no converged value and no estimate.
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
    double      observed_order = 0; // p with r = 2^-p (assumed when only two values exist)
    bool        order_observed = false;
    std::string note;               // why there is no estimate, or that the order was assumed
  };

  // values: Q on successive uniform refinements (cell size halved each time), last the finest.
  // assumed_order: the order used when only two values exist (e.g. element degree + 1).
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values, double assumed_order);
} // namespace compliant
