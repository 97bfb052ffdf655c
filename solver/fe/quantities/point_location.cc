#include "quantities/point_location.h"

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/geometry_info.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/reference_cell.h>

namespace compliant
{
  template <int dim>
  std::pair<typename dealii::DoFHandler<dim>::active_cell_iterator, dealii::Point<dim>>
  owned_cell_around(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dofs,
                    const dealii::Point<dim> &p)
  {
    using namespace dealii;
    // Quadrilaterals and hexahedra: deal.II's search, whose choice among the cells sharing a face
    // does not depend on the partition (raw stresses there differ from cell to cell).
    if (dofs.get_triangulation().all_reference_cells_are_hyper_cube())
      {
        try
          {
            const auto found = GridTools::find_active_cell_around_point(mapping, dofs, p);
            // deal.II 9.4 returns an invalid iterator (rather than throwing) for outside points.
            if (found.first.state() == IteratorState::valid && found.first->is_locally_owned())
              return {found.first, GeometryInfo<dim>::project_to_unit_cell(found.second)};
          }
        catch (...)
          {
          }
        return {typename DoFHandler<dim>::active_cell_iterator(), Point<dim>()};
      }
    // Unit-coordinate tolerance: a point on a face or vertex belongs to every cell there.
    constexpr double inside_tolerance = 1e-8;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          // Vertex boxes miss the bulge of cells mapped onto curved boundaries.
          auto box = cell->bounding_box();
          box.extend(0.25 * cell->diameter());
          if (!box.point_inside(p))
            continue;
          try
            {
              const Point<dim> unit = mapping.transform_real_to_unit_cell(cell, p);
              if (cell->reference_cell().contains_point(unit, inside_tolerance))
                return {cell, unit};
            }
          catch (const typename Mapping<dim>::ExcTransformationFailed &)
            {
              // Newton's inversion failed: p is far outside this cell.
            }
        }
    return {typename DoFHandler<dim>::active_cell_iterator(), Point<dim>()};
  }

  template std::pair<dealii::DoFHandler<2>::active_cell_iterator, dealii::Point<2>>
  owned_cell_around(const dealii::Mapping<2> &, const dealii::DoFHandler<2> &, const dealii::Point<2> &);
  template std::pair<dealii::DoFHandler<3>::active_cell_iterator, dealii::Point<3>>
  owned_cell_around(const dealii::Mapping<3> &, const dealii::DoFHandler<3> &, const dealii::Point<3> &);
} // namespace compliant
