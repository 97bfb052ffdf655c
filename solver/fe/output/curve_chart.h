// The load-displacement curve of a nonlinear run as an SVG chart, drawn from curve.csv: the load
// factor against the motion that changes most (a rigid or best-fit rotation if the run reports one,
// else the displacement with the largest range), one dot per converged step.
#pragma once

#include <string>

namespace compliant
{
  // "" when the curve has fewer than two steps or no motion column.
  std::string draw_load_displacement(const std::string &csv_text, const std::string &title,
                                     const std::string &length_unit);
} // namespace compliant
