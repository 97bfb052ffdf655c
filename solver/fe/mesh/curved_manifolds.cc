#include "mesh/curved_manifolds.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/manifold_lib.h>

#include "mesh/curved_simplex_mapping.h"
#include "mesh/sampled_manifold.h"

#include <algorithm>
#include <limits>
#include <memory>
#include <array>

namespace compliant
{
  namespace
  {
    bool fits_dimension(const CurvedBoundary &boundary, const int dim)
    {
      const bool plane = boundary.shape == CurvedBoundary::circle || boundary.shape == CurvedBoundary::sampled_curve;
      return dim == 2 ? plane : !plane;
    }
  } // namespace

  template <int dim>
  unsigned int mark_curved_faces(dealii::Triangulation<dim> &triangulation,
                                 const std::vector<CurvedBoundary> &boundaries)
  {
    // Face centres of all entities sorted by x: each mesh face looks up a narrow x window.
    struct Centre
    {
      std::array<double, 3> x;
      unsigned int          boundary;
    };
    std::vector<Centre> centres;
    for (unsigned int b = 0; b < boundaries.size(); ++b)
      if (fits_dimension(boundaries[b], dim))
        for (std::size_t i = 0; i + 2 < boundaries[b].face_centres.size(); i += 3)
          centres.push_back({{boundaries[b].face_centres[i], boundaries[b].face_centres[i + 1],
                              boundaries[b].face_centres[i + 2]},
                             b});
    if (centres.empty())
      return 0;
    std::sort(centres.begin(), centres.end(), [](const Centre &a, const Centre &b) { return a.x[0] < b.x[0]; });

    unsigned int n_marked = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        {
          if (face->manifold_id() != dealii::numbers::flat_manifold_id)
            continue; // marked from its other cell
          const auto   centre    = face->center();
          const double tolerance = 1e-6 * face->diameter();
          auto         it        = std::lower_bound(centres.begin(), centres.end(), centre[0] - tolerance,
                                       [](const Centre &c, const double x) { return c.x[0] < x; });
          for (; it != centres.end() && it->x[0] <= centre[0] + tolerance; ++it)
            {
              double distance_squared = 0;
              for (unsigned int d = 0; d < dim; ++d)
                distance_squared += (it->x[d] - centre[d]) * (it->x[d] - centre[d]);
              if (distance_squared <= tolerance * tolerance)
                {
                  face->set_all_manifold_ids(it->boundary);
                  ++n_marked;
                  break;
                }
            }
        }
    return n_marked;
  }

  namespace
  {
    template <int dim>
    bool has_curved_line(const typename dealii::Triangulation<dim>::cell_iterator &cell)
    {
      for (unsigned int l = 0; l < cell->n_lines(); ++l)
        if (cell->line(l)->manifold_id() != dealii::numbers::flat_manifold_id)
          return true;
      return false;
    }

    // min/max of the Jacobian determinant over points spread through the cell.
    template <int dim>
    double jacobian_quality(dealii::FEValues<dim> &values, const typename dealii::Triangulation<dim>::cell_iterator &cell)
    {
      values.reinit(cell);
      double smallest = std::numeric_limits<double>::max(), largest = 0;
      for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
        {
          const double det = values.jacobian(q).determinant();
          smallest         = std::min(smallest, det);
          largest          = std::max(largest, std::abs(det));
        }
      return largest > 0 ? smallest / largest : -1;
    }
  } // namespace

  template <int dim>
  unsigned int straighten_folding_faces(dealii::Triangulation<dim> &triangulation, const unsigned int degree)
  {
    const unsigned int mapping_degree = std::max(2u, degree);
    const bool         simplex        = triangulation.all_reference_cells_are_simplex();
    if (!simplex && !triangulation.all_reference_cells_are_hyper_cube())
      return 0;
    std::unique_ptr<dealii::Mapping<dim>>          curved, straight;
    std::unique_ptr<dealii::FiniteElement<dim>>    fe;
    std::unique_ptr<dealii::Quadrature<dim>>       points;
    if (simplex)
      {
        curved   = std::make_unique<CurvedSimplexMapping<dim>>(2); // deal.II 9.4: simplices to degree 2
        straight = std::make_unique<CurvedSimplexMapping<dim>>(1);
        fe       = std::make_unique<dealii::FE_SimplexP<dim>>(1);
        points   = std::make_unique<dealii::QGaussSimplex<dim>>(4);
      }
    else
      {
        curved   = std::make_unique<dealii::MappingQ<dim>>(mapping_degree);
        straight = std::make_unique<dealii::MappingQ<dim>>(1);
        fe       = std::make_unique<dealii::FE_Q<dim>>(1);
        // Gauss-Lobatto points reach the corners, where a fold shows first.
        points   = std::make_unique<dealii::QGaussLobatto<dim>>(mapping_degree + 2);
      }
    dealii::FEValues<dim> curved_values(*curved, *fe, *points, dealii::update_jacobians);
    dealii::FEValues<dim> straight_values(*straight, *fe, *points, dealii::update_jacobians);

    unsigned int n_straightened = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      {
        if (!has_curved_line<dim>(cell))
          continue;
        if (jacobian_quality(curved_values, cell) >= 0.25 * jacobian_quality(straight_values, cell))
          continue;
        for (const auto &face : cell->face_iterators())
          if (face->manifold_id() != dealii::numbers::flat_manifold_id)
            {
              face->set_all_manifold_ids(dealii::numbers::flat_manifold_id);
              ++n_straightened;
            }
        for (unsigned int l = 0; l < cell->n_lines(); ++l) // an edge on the surface, in 3D
          cell->line(l)->set_manifold_id(dealii::numbers::flat_manifold_id);
      }
    return n_straightened;
  }

  template <int dim>
  void attach_curved_manifolds(dealii::Triangulation<dim> &triangulation,
                               const std::vector<CurvedBoundary> &boundaries)
  {
    for (unsigned int b = 0; b < boundaries.size(); ++b)
      {
        const auto &boundary = boundaries[b];
        if (!fits_dimension(boundary, dim))
          continue;
        dealii::Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = boundary.centre[d];
        if (boundary.shape == CurvedBoundary::sampled_curve || boundary.shape == CurvedBoundary::sampled_surface)
          triangulation.set_manifold(b, SampledManifold<dim>(std::make_shared<const SampledShape>(boundary.samples)));
        else if (boundary.shape == CurvedBoundary::cylinder)
          {
            dealii::Tensor<1, 3> axis;
            dealii::Point<3>     on_axis;
            for (unsigned int d = 0; d < 3; ++d)
              axis[d] = boundary.axis[d], on_axis[d] = boundary.centre[d];
            if constexpr (dim == 3)
              triangulation.set_manifold(b, dealii::CylindricalManifold<3>(axis, on_axis));
          }
        else
          triangulation.set_manifold(b, dealii::SphericalManifold<dim>(centre));
      }
  }

  template unsigned int mark_curved_faces<2>(dealii::Triangulation<2> &, const std::vector<CurvedBoundary> &);
  template unsigned int mark_curved_faces<3>(dealii::Triangulation<3> &, const std::vector<CurvedBoundary> &);
  template unsigned int straighten_folding_faces<2>(dealii::Triangulation<2> &, unsigned int);
  template unsigned int straighten_folding_faces<3>(dealii::Triangulation<3> &, unsigned int);
  template void attach_curved_manifolds<2>(dealii::Triangulation<2> &, const std::vector<CurvedBoundary> &);
  template void attach_curved_manifolds<3>(dealii::Triangulation<3> &, const std::vector<CurvedBoundary> &);
} // namespace compliant
