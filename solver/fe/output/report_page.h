// report.html: one self-contained page per run for a design review (no network: styles inline,
// pictures as data URIs): the case, model, mesh and solver, every quantity with its error estimate,
// the closed-form comparisons with every validity warning, the pictures, the timings and the case
// file itself. Values are printed from the same RunSummary as summary.json, to 8 digits like the
// terminal table; each row carries the full value in data-value for checking tools.
#pragma once

#include "output/summary.h"

#include <string>
#include <vector>

namespace compliant
{
  struct Picture
  {
    std::string file;    // "picture.svg", "mode_1.svg", ...
    std::string caption;
    std::string svg;
  };

  std::string report_html(const RunSummary &summary, const std::string &case_text,
                          const std::vector<Picture> &pictures, double picture_seconds);
} // namespace compliant
