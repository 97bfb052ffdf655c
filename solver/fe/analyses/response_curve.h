// The response curve of a nonlinear run (curve.csv): one line per converged step, its load factor,
// Newton iterations, the path driver's own columns (arc length, stability) and every quantity.
// Rewritten whole under a temporary name and renamed after every step, so that a run stopped at any
// moment leaves a complete curve of its converged steps, never a torn line. Only the root rank writes.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace compliant
{
  class ResponseCurve
  {
  public:
    ResponseCurve(std::string file, bool root);

    // The columns are fixed by the first step: the path's columns, then the quantities (timings left out).
    void add(unsigned int step, double load_factor, unsigned int newton_iterations,
             const std::vector<std::pair<std::string, double>> &path_columns,
             const std::map<std::string, double>                &quantities);
    // A run without a converged step still leaves a curve saying what it would hold.
    void finish();

    const std::string file;

  private:
    void write() const;

    const bool               root;
    std::string              text;
    std::vector<std::string> columns;
    bool                     started = false;
  };
} // namespace compliant
