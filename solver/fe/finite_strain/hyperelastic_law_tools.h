// Tensor helpers shared by the hyperelastic laws' files (internal to finite_strain).
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace compliant::law_tools
{
  using namespace dealii;

  // (C^-1 (x) C^-1) symmetrised: I_ijkl = (Ci_ik Ci_jl + Ci_il Ci_jk) / 2 = -dC^-1/dC
  template <int dim>
  SymmetricTensor<4, dim> inverse_product(const SymmetricTensor<2, dim> &Ci)
  {
    SymmetricTensor<4, dim> result;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        for (unsigned int k = 0; k < dim; ++k)
          for (unsigned int l = k; l < dim; ++l)
            result[i][j][k][l] = 0.5 * (Ci[i][k] * Ci[j][l] + Ci[i][l] * Ci[j][k]);
    return result;
  }

  // ln J = ln sqrt(det(I + H)) with H = 2E, computed without forming det - 1 by subtraction.
  template <int dim>
  double log_J(const SymmetricTensor<2, dim> &E)
  {
    const SymmetricTensor<2, dim> H  = 2 * E;
    const double                  tr = trace(H);
    double det_minus_one = tr + determinant(H);
    if (dim == 3)
      det_minus_one += 0.5 * (tr * tr - H * H);
    return 0.5 * std::log1p(det_minus_one);
  }
} // namespace compliant::law_tools
