// A curve (2D) or surface (3D) known by samples of its gmsh parametrization (mesh/sampled_geometry.h)
// as a deal.II manifold: a new point between existing ones is their weighted average projected
// onto the shape, as for any curved boundary whose closed form is unknown (ellipses, splines, CAD
// patches). Refinement and the mapping's support points then lie on the true boundary.
#pragma once

#include <deal.II/grid/manifold.h>

#include "mesh/sampled_geometry.h"

#include <memory>

namespace compliant
{
  template <int dim>
  class SampledManifold : public dealii::Manifold<dim, dim>
  {
  public:
    explicit SampledManifold(std::shared_ptr<const SampledShape> shape);

    std::unique_ptr<dealii::Manifold<dim, dim>> clone() const override;

    dealii::Point<dim> get_new_point(const dealii::ArrayView<const dealii::Point<dim>> &surrounding_points,
                                     const dealii::ArrayView<const double>             &weights) const override;

    dealii::Point<dim> project_to_manifold(const dealii::ArrayView<const dealii::Point<dim>> &surrounding_points,
                                           const dealii::Point<dim> &candidate) const override;

  private:
    std::shared_ptr<const SampledShape> shape; // shared by clones: the samples are large and fixed
  };
} // namespace compliant
