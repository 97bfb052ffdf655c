// Fields for ParaView: HDF5 + XDMF with displacement, strain, stress, von Mises, material and
// partition id. Files appear under their final names only when complete.
#pragma once


#include <string>

namespace compliant
{
  // Returns the path of the .xdmf file.
  // Problem: LinearElasticProblem<dim> or FiniteStrainProblem<dim>.
  template <class Problem>
  std::string write_fields(const Problem &problem, const std::string &directory);
} // namespace compliant
