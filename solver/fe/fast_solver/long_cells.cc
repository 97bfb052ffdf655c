#include "fast_solver/long_cells.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/grid/grid_tools.h>

#include <algorithm>
#include <array>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace
  {
    // The mean length of the cell's edges in each reference direction.
    template <int dim, typename CellIterator>
    std::array<double, dim> extents(const CellIterator &cell)
    {
      std::array<double, dim> extent{};
      for (unsigned int d = 0; d < dim; ++d)
        {
          for (unsigned int v = 0; v < (1u << dim); ++v)
            if (!(v & (1u << d)))
              extent[d] += cell->vertex(v).distance(cell->vertex(v | (1u << d)));
          extent[d] /= 1u << (dim - 1);
        }
      return extent;
    }

    // The part's thickness through `cell` along its direction d: its extent plus the extents of
    // the cells beyond its faces 2d and 2d + 1, on through opposite faces to the surface, stopped
    // once past `limit`. 0 (thin) where the sheet meets a cell this rank does not see or a refined
    // neighbour: the verdict it then keeps is the long one, the space's without this test.
    template <int dim, typename CellIterator>
    double thickness_through(const CellIterator &cell, const unsigned int d, const double limit)
    {
      double total = extents<dim>(cell)[d];
      for (unsigned int side = 0; side < 2; ++side)
        {
          auto         current = cell;
          unsigned int face    = 2 * d + side;
          while (total <= limit && !current->at_boundary(face))
            {
              if (current->neighbor(face)->has_children() || current->neighbor_is_coarser(face))
                return 0;
              const auto next = current->neighbor(face);
              if (next->is_artificial())
                return 0;
              const unsigned int entry = current->neighbor_of_neighbor(face);
              total += extents<dim>(next)[entry / 2];
              current = next;
              face    = entry ^ 1u; // faces 2k and 2k + 1 are opposite
            }
        }
      return total;
    }
  } // namespace

  template <int dim>
  LongCells find_long_cells(const Triangulation<dim> &mesh, const double aspect_threshold, const double slenderness)
  {
    LongCells result;
    result.mask.assign(mesh.n_active_cells(), 0);
    double largest_linear = 1;
    for (const auto &cell : mesh.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const auto         extent   = extents<dim>(cell);
          const unsigned int shortest = std::min_element(extent.begin(), extent.end()) - extent.begin();
          unsigned int       mask     = 0;
          double             longest  = 0;
          for (unsigned int d = 0; d < dim; ++d)
            if (extent[d] >= aspect_threshold * extent[shortest])
              mask |= 1u << d, longest = std::max(longest, extent[d]);
          if (mask != 0)
            {
              // Across each short direction (a square beam cell has two): the thinnest.
              double thickness = slenderness * longest * 2;
              for (unsigned int d = 0; d < dim; ++d)
                if (!(mask & (1u << d)))
                  thickness = std::min(thickness, thickness_through<dim>(cell, d, slenderness * longest));
              for (unsigned int d = 0; d < dim; ++d)
                if ((mask & (1u << d)) && thickness > slenderness * extent[d])
                  mask &= ~(1u << d);
            }
          for (unsigned int d = 0; d < dim; ++d)
            if (!(mask & (1u << d)))
              largest_linear = std::max(largest_linear, extent[d] / extent[shortest]);
          result.mask[cell->active_cell_index()] = mask;
        }
    // Ghost cells take their owner's verdict: a walk from a ghost could leave what this rank sees.
    if (const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(&mesh))
      {
        GridTools::exchange_cell_data_to_ghosts<std::uint8_t, Triangulation<dim>>(
          mesh, [&](const auto &cell) { return result.mask[cell->active_cell_index()]; },
          [&](const auto &cell, const std::uint8_t mask) { result.mask[cell->active_cell_index()] = mask; });
        largest_linear = Utilities::MPI::max(largest_linear, parallel_mesh->get_communicator());
      }
    result.largest_linear_aspect_ratio = largest_linear;
    return result;
  }

  template LongCells find_long_cells<2>(const Triangulation<2> &, double, double);
  template LongCells find_long_cells<3>(const Triangulation<3> &, double, double);
} // namespace compliant::fast_solver
