// Discretization error of a quantity of interest from a sequence of refined solutions (Richardson
// extrapolation with the observed order). With Q_k = Q + C h_k^p, three solutions give p from
// (Q_k - Q_(k-1)) / (Q_(k-1) - Q_(k-2)) = (h_k^p - h_(k-1)^p) / (h_(k-1)^p - h_(k-2)^p), and the
// error left in Q_k is (Q_k - Q_(k-1)) h_k^p / (h_(k-1)^p - h_k^p). Uniform refinement halves h;
// adaptive refinement gives any decreasing h (the caller uses h = N^(-1/dim) from the DoF counts).
// With only two solutions the order is assumed; when the differences do not shrink at least like
// h^0.5 (a stress singularity, a peak at a re-entrant corner) there is no converged value and no
// estimate. Nor is there one the sequence cannot vouch for (the guards): successive differences of
// opposite sign (a non-monotone sequence: the extrapolation model Q + C h^p has one sign), or an
// observed order above what the element can attain (a coincidence of pre-asymptotic errors: a
// stress at a hole's edge fitted at order 4.83 on Q2 gave an estimate 1/125 of the true error).
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
  // unit, strictly decreasing); assumed_order: the order used when only two values exist;
  // attainable_order: the fastest convergence in h the discretization allows (0: no bound, e.g.
  // rungs that raise the degree), see attainable_order() below.
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values,
                                              const std::vector<double> &sizes, double assumed_order,
                                              double attainable_order = 0);

  // Uniform refinement: h halves from one value to the next.
  ErrorEstimate estimate_discretization_error(const std::vector<double> &values, double assumed_order,
                                              double attainable_order = 0);

  // The fastest any quantity of a degree-p solution converges in h: 2p (the energy, and a goal
  // functional whose dual is smooth, at h^p times h^p; displacements at points h^(p+1), stresses
  // h^p), with 15 % room for the scatter of an order fitted from three values on graded or
  // adaptive meshes.
  inline double attainable_order(const unsigned int degree) { return 1.15 * 2 * degree; }
} // namespace compliant
