// Von Mises stress of a 2D or 3D stress state; in 2D the out-of-plane normal stress is given
// (zero in plane stress) and the out-of-plane shear stresses vanish.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace compliant
{
  template <int dim>
  double von_mises_stress(const dealii::SymmetricTensor<2, dim> &s, const double sigma_zz)
  {
    double s3[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, sigma_zz}};
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        s3[i][j] = s[i][j];
    const double a = s3[0][0] - s3[1][1], b = s3[1][1] - s3[2][2], c = s3[2][2] - s3[0][0];
    return std::sqrt(0.5 * (a * a + b * b + c * c) +
                     3 * (s3[0][1] * s3[0][1] + s3[1][2] * s3[1][2] + s3[0][2] * s3[0][2]));
  }
} // namespace compliant
