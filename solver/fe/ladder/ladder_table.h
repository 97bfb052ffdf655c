// The ladder's record of its rungs (plain C++): one line per rung printed as it ends, and
// ladder.csv (rung, model, degree, refinements, adaptive cycles, DoFs, seconds, cumulative seconds,
// then per target quantity its value, its Richardson estimate and the estimate the stop rule read).
#pragma once

#include "ladder/error_estimate.h"
#include "ladder/ladder_row.h"

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace compliant
{
  struct Rung
  {
    std::string  model = "linear";
    unsigned int degree = 0, refinements = 0, adaptive_cycles = 0;
    double       dofs = 0, seconds = 0;
    std::map<std::string, double>        values;
    std::map<std::string, ErrorEstimate> estimates;
    // The estimate the stop rule reads: the Richardson one, times the safety factor while the
    // observed order is not steady (adaptive and degree rungs); negative when there is none.
    std::map<std::string, double> stop_estimates;
    // Quantities/Error estimates: the dual-weighted estimate of each (relative); the stop reads it
    // where the Richardson estimate is missing or untrusted.
    std::map<std::string, double> dual_estimates;
    std::string                   decision;

    // What the stop rule read for quantity n (the bare estimate when it read none).
    double stop_or_bare_estimate(const std::string &n) const;
  };

  // "  (d) rung N: model, degree, refinements[, + adaptive], DoFs, s; name = value (estimate ...); decision"
  void print_rung(std::ostream &out, const Rung &rung, std::size_t number, bool show_adaptive);

  // The rung's line of ladder.csv without its number and cumulative time; plane_stress_prefix
  // marks the rungs of a plane-stress model standing for a 3D part.
  LadderRow ladder_row(const Rung &rung, const std::vector<std::string> &names, bool plane_stress_prefix);

  // Writes directory/ladder.csv (through a temporary file, renamed when complete).
  void write_ladder_csv(const std::string &directory, const std::vector<std::string> &names,
                        const std::vector<LadderRow> &rows);
} // namespace compliant
