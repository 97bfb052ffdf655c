#include "mesh/mesh_reader.h"

#include <deal.II/grid/grid_in.h>

#include <sstream>

namespace compliant
{
  template <int dim>
  void create_triangulation(dealii::Triangulation<dim> &triangulation,
                            const MeshedGeometry &geometry, const unsigned int global_refinements)
  {
    dealii::GridIn<dim> grid_in;
    grid_in.attach_triangulation(triangulation);
    std::istringstream in(geometry.msh_text);
    grid_in.read_msh(in);
    triangulation.refine_global(global_refinements);
  }

  template void create_triangulation<2>(dealii::Triangulation<2> &, const MeshedGeometry &, unsigned int);
  template void create_triangulation<3>(dealii::Triangulation<3> &, const MeshedGeometry &, unsigned int);
} // namespace compliant
