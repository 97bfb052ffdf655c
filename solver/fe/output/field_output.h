// Fields for ParaView: HDF5 + XDMF with displacement, strain, stress, von Mises, material and
// partition id. Files appear under their final names only when complete.
#pragma once

#include "elasticity/linear_elastic_problem.h"

#include <string>

namespace compliant
{
  // Returns the path of the .xdmf file.
  template <int dim>
  std::string write_fields(const LinearElasticProblem<dim> &problem, const std::string &directory);
} // namespace compliant
