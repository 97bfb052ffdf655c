#include "fast_solver/amg_coarse_solver.h"

#include "linear_algebra/petsc_linear_solver.h"

#include <stdexcept>

namespace compliant::fast_solver
{
  AmgCoarseSolver::AmgCoarseSolver(dealii::PETScWrappers::MPI::SparseMatrix         &matrix,
                                   std::vector<dealii::PETScWrappers::MPI::Vector> rigid_body_modes,
                                   const unsigned int block_size, const std::string &petsc_options)
  {
    const auto owned = matrix.locally_owned_range_indices();
    rhs.reinit(owned, matrix.get_mpi_communicator());
    correction.reinit(owned, matrix.get_mpi_communicator());
    pc = create_gamg_preconditioner(matrix, rigid_body_modes, block_size, petsc_options);
  }

  AmgCoarseSolver::~AmgCoarseSolver()
  {
    if (pc)
      PCDestroy(&pc);
  }

  void AmgCoarseSolver::operator()(const unsigned int, VectorType &dst, const VectorType &src) const
  {
    // Both vectors number the same owned DoFs in the same order: copy the local parts.
    const unsigned int n = src.locally_owned_size();
    {
      PetscScalar *values;
      VecGetArray(rhs, &values);
      for (unsigned int i = 0; i < n; ++i)
        values[i] = src.local_element(i);
      VecRestoreArray(rhs, &values);
    }
    if (PCApply(pc, rhs, correction) != 0)
      throw std::runtime_error("coarse AMG (PETSc GAMG) failed to apply");
    const PetscScalar *values;
    VecGetArrayRead(correction, &values);
    for (unsigned int i = 0; i < n; ++i)
      dst.local_element(i) = values[i];
    VecRestoreArrayRead(correction, &values);
  }
} // namespace compliant::fast_solver
