// The largest cell aspect ratio of a mesh (longest over shortest edge of a cell, the largest over
// the cells every rank owns): thin parts mesh into long cells, which weaken pointwise smoothers
// and aggregation AMG; the fast solver sizes its smoother and coarse solve from this number.
#pragma once

#include <deal.II/grid/tria.h>

#include <mpi.h>

namespace compliant
{
  template <int dim>
  double largest_cell_aspect_ratio(const dealii::Triangulation<dim> &triangulation, MPI_Comm communicator);
} // namespace compliant
