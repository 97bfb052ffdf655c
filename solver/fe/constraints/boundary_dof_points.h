// The DoFs that lie on a named boundary, with their component and support point, over the whole
// (shared) triangulation, so every rank gets the same list.
#pragma once

#include <deal.II/base/point.h>

#include "discretization/discretization.h"

#include <map>

namespace compliant
{
  template <int dim>
  struct DofPoint
  {
    unsigned int       component;
    dealii::Point<dim> point;
  };

  // Keyed by global DoF index.
  template <int dim>
  std::map<dealii::types::global_dof_index, DofPoint<dim>>
  boundary_dof_points(const Discretization<dim> &problem, int boundary_id);
} // namespace compliant
