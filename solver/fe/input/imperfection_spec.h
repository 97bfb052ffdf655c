// Geometry/Imperfection: the perfect geometry shifted by buckling mode shapes of named amplitude
// before a nonlinear run, so a path that would meet a bifurcation follows the buckled branch.
// Plain C++: parsed once here, typed from then on.
#pragma once

#include <string>
#include <vector>

namespace compliant
{
  struct ImperfectionMode
  {
    unsigned int mode;      // buckling mode number, 1 = the factor nearest zero
    double       amplitude; // the mode's largest displacement component, in the case's length unit
  };

  // "<mode>: <amplitude>[, <mode>: <amplitude> ...]", e.g. "1: 0.01" or "1: 0.01, 2: -0.002";
  // empty: none. Throws std::invalid_argument saying what was expected.
  std::vector<ImperfectionMode> parse_imperfection(const std::string &text);
} // namespace compliant
