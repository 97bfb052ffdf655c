// The ladder's stop rule (plain C++): which estimate of a quantity's discretization error may end
// the climb. Only an observed order ends it: an assumed one is optimistic at singularities.
// Adaptive meshes converge unevenly while the refinement finds the singular corners (Cook's
// membrane: observed orders 2.8, 6.2, 3.9 on the first rungs, estimates 6x too small): there the
// order must also hold steady over two successive triples (within a factor 1.5). Degree rungs
// likewise: convergence in N speeds up with the degree on smooth problems and is algebraic at
// singularities. While the order is not steady the estimate is multiplied by a safety factor: 10
// on adaptive rungs (the worst effectivity on such rungs of Cook's membrane was 0.16), 8 on a
// triple of degrees (bare effectivities 0.32 on Cook, 0.23 on the torsion bar: the convergence in
// N slows from degree 3 to 4; 8 x puts them at 2.5 and 1.8).
#pragma once

#include "ladder/error_estimate.h"

#include <map>
#include <string>

namespace compliant
{
  class StopRule
  {
  public:
    explicit StopRule(bool degree_rungs) : degree_rungs(degree_rungs) {}

    // The safety factor depends on the kind of rungs the linear climb takes (degree or adaptive).
    void set_degree_rungs(bool degree) { degree_rungs = degree; }
    double      safety_factor() const { return degree_rungs ? 8.0 : 10.0; }
    std::string safety_factor_text() const;

    // The estimate the stop rule reads for quantity `name` (negative without an observed order):
    // the Richardson one, times the safety factor while the observed order is not steady. uneven:
    // adaptive or degree rungs, whose order must hold steady over two successive triples.
    double stop_estimate(const std::string &name, const ErrorEstimate &estimate, bool uneven);

    // Why a rung goes on: each quantity's missing or too large estimate ("" if none).
    std::string why_go_on(const std::map<std::string, ErrorEstimate> &estimates, double target) const;

    // A new climb (finite strain after linear): no orders observed yet.
    void restart();

  private:
    bool                               degree_rungs;
    std::map<std::string, double>      orders;   // last observed order per quantity (0: none)
    std::map<std::string, std::string> unsteady; // why an estimate cannot stop the climb yet
  };
} // namespace compliant
