// Builds a triangulation from the Gmsh text of MeshedGeometry (every rank gets the whole mesh;
// a parallel::shared triangulation partitions it with METIS).
#pragma once

#include <deal.II/grid/tria.h>

#include "mesh/gmsh_geometry.h"

namespace compliant
{
  template <int dim>
  void create_triangulation(dealii::Triangulation<dim> &triangulation,
                            const MeshedGeometry &geometry, unsigned int global_refinements);
} // namespace compliant
