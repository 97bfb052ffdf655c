// Refuses a refinement that cannot fit in memory before allocating it: a mistyped refinement level
// (or a ladder climbing one rung too far) otherwise grows the mesh by 2^dim per level until the
// kernel kills the run without a word. The estimate is a lower bound (every rank holds the whole
// mesh: ~1 kB per cell per rank, and ~0.5 kB per DoF, the matrix-free minimum; measured 0.6 kB per
// DoF on the 1.05M-DoF cantilever, and a 2D Q2 ladder rung of 33.6M DoFs on 4.2M cells was killed
// at 24 GB on 2 ranks), compared with MemAvailable.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace compliant
{
  struct ModelTooLarge : std::invalid_argument
  {
    using std::invalid_argument::invalid_argument;
  };

  // MemAvailable of /proc/meminfo in bytes, or 0 where it cannot be read.
  double available_memory();

  // The cells a mesh may have when every one of `ranks` ranks holds it whole, at ~1 kB per cell
  // per rank: MemAvailable / (1 kB x ranks); 0 where the available memory cannot be read.
  std::uint64_t automatic_maximum_cells(unsigned int ranks);

  // Throws ModelTooLarge naming the refinement, the estimate and the memory available; does
  // nothing where the available memory cannot be read.
  void refuse_refinement_beyond_memory(std::uint64_t coarse_cells, unsigned int dim,
                                       unsigned int global_refinements, unsigned int degree,
                                       unsigned int ranks);
} // namespace compliant
