// Many runs of one case in one process (a parameter study's points): the libraries, MPI and
// PETSc start once, and each point pays only its meshing, solve and output. A points file has
// one point per line: its output directory, then its "Section/Name=value" overrides, separated
// by tabs. Each point's outcome goes to <points file>.status as it ends ("K<TAB>ok" or
// "K<TAB>failed<TAB>message"); a failed point leaves no output and the batch goes on.
#pragma once

#include <mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace compliant
{
  struct BatchPoint
  {
    std::string              output_directory;
    std::vector<std::string> overrides;
  };

  // The points of a points file. Throws std::runtime_error naming the file and line.
  std::vector<BatchPoint> read_batch_points(const std::string &file);

  // Runs run_point(point) for each point (it throws on failure, on every rank alike: a failure on
  // some ranks only cannot be recovered from, `all_failed` decides and aborts otherwise). Returns
  // 0 if every point ran, 3 if some failed.
  int run_batch(const std::string &points_file, const std::vector<BatchPoint> &points,
                const std::function<void(const BatchPoint &)> &run_point,
                const std::function<bool()> &all_failed, MPI_Comm comm);
} // namespace compliant
