#include "mesh/curved_simplex_mapping.h"

#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/grid/tria_accessor.h>
#include <deal.II/grid/tria_iterator.h>

namespace compliant
{
  template <int dim>
  CurvedSimplexMapping<dim>::CurvedSimplexMapping(const unsigned int degree)
    : dealii::MappingFE<dim>(dealii::FE_SimplexP<dim>(degree))
  {}

  template <int dim>
  std::unique_ptr<dealii::Mapping<dim>> CurvedSimplexMapping<dim>::clone() const
  {
    return std::make_unique<CurvedSimplexMapping<dim>>(this->polynomial_degree);
  }

  template <int dim>
  std::vector<dealii::Point<dim>> CurvedSimplexMapping<dim>::compute_mapping_support_points(
    const typename dealii::Triangulation<dim>::cell_iterator &cell) const
  {
    auto points = dealii::MappingFE<dim>::compute_mapping_support_points(cell);
    // At degree 2 the support points are the vertices and the edge midpoints (on the chord here).
    for (const unsigned int l : cell->line_indices())
      {
        const auto line = cell->line(l);
        if (line->manifold_id() == dealii::numbers::flat_manifold_id)
          continue;
        const dealii::Point<dim> chord_midpoint = 0.5 * (line->vertex(0) + line->vertex(1));
        for (auto &point : points)
          if (point.distance(chord_midpoint) < 1e-12 * line->diameter())
            point = line->center(/*respect_manifold=*/true);
      }
    return points;
  }

  template class CurvedSimplexMapping<2>;
  template class CurvedSimplexMapping<3>;
} // namespace compliant
