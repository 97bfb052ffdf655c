#include "mesh/cell_aspect_ratio.h"

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <limits>

namespace compliant
{
  template <int dim>
  double largest_cell_aspect_ratio(const dealii::Triangulation<dim> &triangulation, MPI_Comm communicator)
  {
    double largest = 1;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double shortest = std::numeric_limits<double>::max(), longest = 0;
          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            {
              const double length = cell->line(l)->diameter();
              shortest = std::min(shortest, length), longest = std::max(longest, length);
            }
          if (shortest > 0)
            largest = std::max(largest, longest / shortest);
        }
    return dealii::Utilities::MPI::max(largest, communicator);
  }

  template double largest_cell_aspect_ratio<2>(const dealii::Triangulation<2> &, MPI_Comm);
  template double largest_cell_aspect_ratio<3>(const dealii::Triangulation<3> &, MPI_Comm);
} // namespace compliant
