// The nodes of one boundary face: each support point of the displacement's element (base
// element 0 of the FESystem) on the face, with its DoF per component and its position. Rigid
// boundaries and contact both work node by node on named boundaries.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace compliant
{
  template <int dim>
  struct FaceNode
  {
    std::array<dealii::types::global_dof_index, dim> dofs{};
    dealii::Point<dim>                               position;
  };

  // fe_values: on the cell's element, its quadrature the displacement element's unit support
  // points, with update_quadrature_points; reinit here. Keyed by the support point's index.
  template <int dim, typename CellIterator>
  std::map<unsigned int, FaceNode<dim>> face_nodes(const CellIterator &cell, const unsigned int face,
                                                   dealii::FEValues<dim> &fe_values)
  {
    const auto &fe = cell->get_fe();
    fe_values.reinit(cell);
    std::vector<dealii::types::global_dof_index> cell_dofs(fe.n_dofs_per_cell()),
      face_dofs(fe.n_dofs_per_face(face));
    cell->get_dof_indices(cell_dofs);
    cell->face(face)->get_dof_indices(face_dofs);
    std::map<unsigned int, FaceNode<dim>> nodes;
    for (unsigned int i = 0; i < cell_dofs.size(); ++i)
      {
        const auto [base_and_copy, base_index] = fe.system_to_base_index(i);
        if (base_and_copy.first != 0 || std::find(face_dofs.begin(), face_dofs.end(), cell_dofs[i]) == face_dofs.end())
          continue;
        auto &node                      = nodes[base_index];
        node.dofs[base_and_copy.second] = cell_dofs[i];
        node.position                   = fe_values.quadrature_point(base_index);
      }
    return nodes;
  }
} // namespace compliant
