// Which directions of each cell the long-edge space (fast_solver/long_edge_space.h) makes
// quadratic. A direction is long where the cell is at least `aspect_threshold` times longer in it
// than in its shortest direction, and the part is thin across the cell: its thickness through the
// cell along a short direction (the sheet of cells from surface to surface; the least over the
// short directions: a beam is thin if either of its sides is) is at most
// `slenderness` times the cell's length in the long direction. Long cells inside a thick body (a block
// meshed in slabs, a mesh graded toward a fillet) bend with the body, not across their own
// thickness: there the degree-1 level does not lock, and quadratic directions would only enlarge
// the factor. Free of the FE space: geometry and the cells' neighbours only.
#pragma once

#include <deal.II/grid/tria.h>

#include <cstdint>
#include <vector>

namespace compliant::fast_solver
{
  struct LongCells
  {
    // By active cell index, on the locally owned and ghost cells (the owner's verdict): bit d set
    // where direction d is long. Zero elsewhere.
    std::vector<std::uint8_t> mask;
    // Over all ranks: the largest ratio of a direction left linear to the cell's shortest, the
    // anisotropy the smoother still has to reach (1 on cubes).
    double largest_linear_aspect_ratio = 1;
    // Over all ranks: some cell long by its aspect ratio alone lies in a thick part.
    bool thick_long_cells = false;
  };

  // On a mesh every rank holds whole (serial, or shared without artificial cells) each rank
  // decides every cell. On a distributed one the owner decides and its ghosts take the verdict;
  // a walk there ends where the rank's cells end, so a part thicker than one rank sees can count
  // as thin (the verdict of the aspect ratio alone).
  template <int dim>
  LongCells find_long_cells(const dealii::Triangulation<dim> &mesh, double aspect_threshold, double slenderness);
} // namespace compliant::fast_solver
