// The locally owned cell that holds a point, for point displacements and point stresses.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <utility>

namespace compliant
{
  // The locally owned cell around p (an invalid iterator if no cell of this rank holds it) and p's
  // unit coordinates there. Quadrilaterals and hexahedra: deal.II's search. Triangles and
  // tetrahedra: a scan of the owned cells' bounding boxes, widened for curved cells, because
  // deal.II 9.4's find_active_cell_around_point crashes on distributed tetrahedral meshes (the
  // thick sphere at 2 refinements on 2 ranks); a point needs only its owners.
  template <int dim>
  std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, dealii::Point<dim>>
  owned_cell_around(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dofs,
                    const dealii::Point<dim> &p);
} // namespace compliant
