#include "constraints/boundary_dof_points.h"

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  std::map<types::global_dof_index, DofPoint<dim>>
  boundary_dof_points(const Discretization<dim> &problem, const int boundary_id)
  {
    std::map<types::global_dof_index, DofPoint<dim>> result;
    const Quadrature<dim> support(problem.fe->get_unit_support_points());
    FEValues<dim> fe_values(*problem.mapping, *problem.fe, support, update_quadrature_points);
    std::vector<types::global_dof_index> dofs(problem.fe->n_dofs_per_cell()), face_dofs;
    // All cells, not only owned ones: the shared triangulation has them all on every rank.
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == boundary_id)
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            // The face's own DoF list (has_support_on_face is not exact for simplex elements).
            face_dofs.resize(problem.fe->n_dofs_per_face(f));
            cell->face(f)->get_dof_indices(face_dofs);
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (std::find(face_dofs.begin(), face_dofs.end(), dofs[i]) != face_dofs.end())
                result[dofs[i]] = {problem.fe->system_to_component_index(i).first,
                                   fe_values.quadrature_point(i)};
          }
    return result;
  }

  template std::map<types::global_dof_index, DofPoint<2>>
  boundary_dof_points<2>(const Discretization<2> &, int);
  template std::map<types::global_dof_index, DofPoint<3>>
  boundary_dof_points<3>(const Discretization<3> &, int);
} // namespace compliant
