// One machine-readable summary per run (JSON), written whole or not at all.
#pragma once

#include "quantities/comparison.h"

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct RunSummary
  {
    std::string                        case_file;
    std::map<std::string, std::string> settings;   // model, mesh file, ...
    std::map<std::string, double>      parameters; // geometry parameters
    std::map<std::string, double>      quantities;
    std::vector<Comparison>            comparisons;
  };

  std::string to_json(const RunSummary &summary);

  // Writes to a temporary name and renames, so a reader never sees half a file.
  void write_summary(const RunSummary &summary, const std::string &file);

  // The table printed at the end of a run.
  std::string format_table(const RunSummary &summary);
} // namespace compliant
