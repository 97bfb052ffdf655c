// The coarsest level of the p-multigrid: one V-cycle of PETSc's smoothed-aggregation AMG (GAMG)
// on the assembled degree-1 matrix, given its block size and the rigid-body modes.
#pragma once

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/multigrid/mg_base.h>

#include <petscpc.h>

#include <string>
#include <vector>

namespace compliant::fast_solver
{
  class AmgCoarseSolver : public dealii::MGCoarseGridBase<dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    // The matrix must outlive this object. 'Linear solver/PETSc options' apply here too.
    AmgCoarseSolver(dealii::PETScWrappers::MPI::SparseMatrix         &matrix,
                    std::vector<dealii::PETScWrappers::MPI::Vector> rigid_body_modes,
                    unsigned int block_size, const std::string &petsc_options);
    ~AmgCoarseSolver() override;
    AmgCoarseSolver(const AmgCoarseSolver &)            = delete;
    AmgCoarseSolver &operator=(const AmgCoarseSolver &) = delete;

    void operator()(const unsigned int level, VectorType &dst, const VectorType &src) const override;

  private:
    PC                                      pc = nullptr;
    mutable dealii::PETScWrappers::MPI::Vector rhs, correction;
  };
} // namespace compliant::fast_solver
