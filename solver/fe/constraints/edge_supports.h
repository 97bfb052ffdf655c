// Supports on edges (3D) or corners (2D): the DoFs that lie on every one of several boundaries,
// e.g. the edges of a plate's bottom face, 'bottom & sides'. NAFEMS FV52 is simply supported
// this way, which no face condition can express.
#pragma once

#include <deal.II/lac/affine_constraints.h>

#include "discretization/discretization.h"

#include <string>

namespace compliant
{
  // spec: 'bottom & sides: z; a & b: x, y'. Holds the named components at zero. DoFs that are
  // constrained already keep their constraint. Throws std::invalid_argument naming `where`.
  template <int dim>
  void add_edge_supports(const Discretization<dim> &problem, const std::string &spec,
                         const std::string &where, dealii::AffineConstraints<double> &constraints);
} // namespace compliant
