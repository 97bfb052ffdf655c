#include "fast_solver/long_cells.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
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
    // once past `limit`. 0 (thin) where the sheet meets a cell this rank does not see, a refined
    // or a coarser neighbour (hanging nodes, which the space excludes anyway): the verdict then
    // kept is the aspect ratio's alone.
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
    const auto *parallel_mesh = dynamic_cast<const parallel::TriangulationBase<dim> *>(&mesh);
    const auto *shared_mesh   = dynamic_cast<const parallel::shared::Triangulation<dim> *>(&mesh);
    // Every rank holds every cell: decide them all here, alike on every rank, without messages.
    const bool whole = parallel_mesh == nullptr || (shared_mesh && !shared_mesh->with_artificial_cells());
    bool       thick = false;
    for (const auto &cell : mesh.active_cell_iterators())
      if (whole || cell->is_locally_owned())
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
                  mask &= ~(1u << d), thick = true;
            }
          for (unsigned int d = 0; d < dim; ++d)
            if (!(mask & (1u << d)))
              result.largest_linear_aspect_ratio =
                std::max(result.largest_linear_aspect_ratio, extent[d] / extent[shortest]);
          result.mask[cell->active_cell_index()] = mask;
        }
    result.thick_long_cells = thick;
    if (parallel_mesh == nullptr)
      return result;
    // Ghost cells take their owner's verdict: a walk from a ghost could leave what this rank sees.
    if (!whole)
      GridTools::exchange_cell_data_to_ghosts<std::uint8_t, Triangulation<dim>>(
        mesh, [&](const auto &cell) { return result.mask[cell->active_cell_index()]; },
        [&](const auto &cell, const std::uint8_t mask) { result.mask[cell->active_cell_index()] = mask; });
    const MPI_Comm comm                = parallel_mesh->get_communicator();
    result.largest_linear_aspect_ratio = Utilities::MPI::max(result.largest_linear_aspect_ratio, comm);
    result.thick_long_cells            = Utilities::MPI::logical_or(thick, comm);
    return result;
  }

  template LongCells find_long_cells<2>(const Triangulation<2> &, double, double);
  template LongCells find_long_cells<3>(const Triangulation<3> &, double, double);
} // namespace compliant::fast_solver
