// Builds a triangulation from the Gmsh text of MeshedGeometry (every rank gets the whole mesh;
// a parallel::shared triangulation partitions it with METIS; a parallel::fullydistributed one
// gets only its METIS part, read and cut on rank 0), refined globally and then locally by
// the given refine flags (one vector per cycle, over the active cells of that cycle; the same on
// every rank, so the ranks build the same mesh). Refuses (ModelTooLarge) global refinements that
// cannot fit in memory at the given element degree, before refining.
#pragma once

#include <deal.II/grid/tria.h>

#include "mesh/gmsh_geometry.h"

#include <vector>

namespace compliant
{
  template <int dim>
  void create_triangulation(dealii::Triangulation<dim> &triangulation,
                            const MeshedGeometry &geometry, unsigned int global_refinements,
                            const std::vector<std::vector<bool>> &adaptive_refinements = {},
                            unsigned int element_degree = 1);
} // namespace compliant
