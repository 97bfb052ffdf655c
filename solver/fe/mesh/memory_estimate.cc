#include "mesh/memory_estimate.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace compliant
{
  double available_memory()
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   key;
    double        kilobytes;
    std::string   unit;
    while (meminfo >> key >> kilobytes >> unit)
      if (key == "MemAvailable:")
        return kilobytes * 1024;
    return 0;
  }

  std::uint64_t automatic_maximum_cells(const unsigned int ranks)
  {
    return static_cast<std::uint64_t>(available_memory() / (1000.0 * std::max(1u, ranks)));
  }

  void refuse_refinement_beyond_memory(const std::uint64_t coarse_cells, const unsigned int dim,
                                       const unsigned int global_refinements, const unsigned int degree,
                                       const unsigned int ranks)
  {
    const double available = available_memory();
    if (available <= 0)
      return;
    const double cells = static_cast<double>(coarse_cells) * std::pow(2.0, dim * global_refinements);
    const double dofs  = dim * cells * std::pow(static_cast<double>(degree), dim);
    const double bytes = 1000 * cells * ranks + 500 * dofs;
    if (bytes <= available)
      return;
    std::ostringstream message;
    message.precision(3);
    message << "Discretization/Global refinements = " << global_refinements << " turns " << coarse_cells
            << " cells into about " << cells << " cells and " << dofs << " DoFs at degree " << degree
            << ", needing at least " << bytes / 1e9 << " GB on " << ranks << " rank(s); this machine has "
            << available / 1e9 << " GB available: use fewer refinements or a coarser mesh";
    throw ModelTooLarge(message.str());
  }
} // namespace compliant
