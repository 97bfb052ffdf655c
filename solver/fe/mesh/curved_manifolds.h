// The curved boundaries gmsh found (mesh/curved_entities.h) as deal.II manifolds: circles,
// cylinders and spheres by their closed forms, any other curve or surface by its samples
// (mesh/sampled_manifold.h). Refinement puts new vertices on the true surface, and a mapping of the
// element's degree curves the cells that touch it.
#pragma once

#include <deal.II/grid/tria.h>

#include "mesh/curved_entities.h"

#include <vector>

namespace compliant
{
  // Gives every face (and its edges) that is a mesh face of a curved entity the manifold id of
  // that entity (its index). Call on the coarse mesh as read, before any refinement; returns the
  // number of faces marked.
  template <int dim>
  unsigned int mark_curved_faces(dealii::Triangulation<dim> &triangulation,
                                 const std::vector<CurvedBoundary> &boundaries);

  // A curved face bulging across a thin cell folds it (a fillet meeting a flat cell: the arc's
  // sagitta near the cell's thickness). Checks every cell with a curved edge under a mapping of
  // degree max(2, degree) (refinement moves midpoints as far) and gives the curved faces of any
  // cell whose Jacobian quality (min/max determinant) falls below a quarter of its straight-sided
  // value back to straight. Call after attach_curved_manifolds, before refinement; returns the
  // number of faces straightened.
  template <int dim>
  unsigned int straighten_folding_faces(dealii::Triangulation<dim> &triangulation, unsigned int degree);

  // Attaches the manifold of each entity under its id (ids travel with a distributed mesh's
  // description; the manifolds do not).
  template <int dim>
  void attach_curved_manifolds(dealii::Triangulation<dim> &triangulation,
                               const std::vector<CurvedBoundary> &boundaries);
} // namespace compliant
