// Reentrant (concave) corners of a 2D mesh boundary. At a corner with interior angle alpha > pi the
// torsional shear stress is infinite, like r^(pi/alpha - 1) (Williams-type corner singularity of
// the harmonic warping function), so a peak stress found there grows with mesh refinement.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace compliant::section
{
  struct BoundaryCorner
  {
    dealii::Point<2> location;
    double           interior_angle = 0; // radians, measured through the material
    double           cell_size      = 0; // largest diameter of the cells touching it
  };

  // Boundary vertices whose interior angle exceeds pi + min_excess (radians). A polygonal fillet
  // turns by small angles at each vertex; min_excess keeps those out.
  std::vector<BoundaryCorner> reentrant_corners(const dealii::Triangulation<2> &triangulation,
                                                double                          min_excess);
} // namespace compliant::section
