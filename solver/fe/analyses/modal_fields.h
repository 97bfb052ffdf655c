// Mode shapes for ParaView: HDF5 + XDMF with one vector field per mode (mode_1, mode_2, ...),
// each scaled to a largest displacement magnitude of 1, plus material and partition id.
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "discretization/discretization.h"

#include <string>
#include <vector>

namespace compliant
{
  // The modes must satisfy the (homogeneous) constraints, i.e. be distributed. Returns the path
  // of the .xdmf file; files appear under their final names only when complete.
  template <int dim>
  std::string write_mode_shapes(const Discretization<dim>                             &problem,
                                const std::vector<dealii::PETScWrappers::MPI::Vector> &modes,
                                const std::string                                     &directory);
} // namespace compliant
