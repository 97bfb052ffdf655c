#include "mesh/sampled_manifold.h"

namespace compliant
{
  namespace
  {
    template <int dim>
    Vector3 as_vector(const dealii::Point<dim> &p)
    {
      Vector3 x = {{0, 0, 0}};
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = p[d];
      return x;
    }
  } // namespace

  template <int dim>
  SampledManifold<dim>::SampledManifold(std::shared_ptr<const SampledShape> shape)
    : shape(std::move(shape))
  {}

  template <int dim>
  std::unique_ptr<dealii::Manifold<dim, dim>> SampledManifold<dim>::clone() const
  {
    return std::make_unique<SampledManifold<dim>>(shape);
  }

  template <int dim>
  dealii::Point<dim> SampledManifold<dim>::get_new_point(const dealii::ArrayView<const dealii::Point<dim>> &surrounding_points,
                                                         const dealii::ArrayView<const double> &weights) const
  {
    dealii::Point<dim> average;
    for (unsigned int k = 0; k < surrounding_points.size(); ++k)
      average += weights[k] * surrounding_points[k];
    return project_to_manifold(surrounding_points, average);
  }

  template <int dim>
  dealii::Point<dim> SampledManifold<dim>::project_to_manifold(const dealii::ArrayView<const dealii::Point<dim>> &,
                                                               const dealii::Point<dim> &candidate) const
  {
    const Vector3      x = shape->closest_point(as_vector(candidate));
    dealii::Point<dim> result;
    for (unsigned int d = 0; d < dim; ++d)
      result[d] = x[d];
    return result;
  }

  template class SampledManifold<2>;
  template class SampledManifold<3>;
} // namespace compliant
