// Displacement of a rigid rotation about an axis through a center, exact (Rodrigues' formula),
// not linearised: u(x) = R (x - c) + c - x.
#pragma once

#include <deal.II/base/function.h>

#include <cmath>

namespace compliant
{
  template <int dim>
  class RigidRotation : public dealii::Function<dim>
  {
  public:
    RigidRotation(double angle, const dealii::Point<3> &center, const dealii::Tensor<1, 3> &axis)
      : dealii::Function<dim>(dim), angle(angle), center(center), axis(axis)
    {}

    void vector_value(const dealii::Point<dim> &p, dealii::Vector<double> &values) const override
    {
      dealii::Tensor<1, 3> r;
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = p[d] - center[d];
      const auto rotated = r * std::cos(angle) + dealii::cross_product_3d(axis, r) * std::sin(angle) +
                           axis * (axis * r) * (1 - std::cos(angle));
      for (unsigned int d = 0; d < dim; ++d)
        values[d] = rotated[d] - r[d];
    }

  private:
    double               angle;
    dealii::Point<3>     center;
    dealii::Tensor<1, 3> axis;
  };
} // namespace compliant
