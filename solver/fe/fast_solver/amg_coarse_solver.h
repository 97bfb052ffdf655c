// The coarsest level of the p-multigrid: PETSc's smoothed-aggregation AMG (GAMG) on the assembled
// degree-1 matrix, given its block size and the rigid-body modes; either one V-cycle (a fixed
// linear operator) or CG preconditioned by it to a relative tolerance (then the outer Krylov
// method must be flexible).
#pragma once

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/multigrid/mg_base.h>

#include <petscksp.h>

#include <string>
#include <vector>

namespace compliant::fast_solver
{
  class AmgCoarseSolver : public dealii::MGCoarseGridBase<dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    // The matrix must outlive this object. 'Linear solver/PETSc options' apply here too.
    // relative_tolerance = 0: one V-cycle; otherwise CG + GAMG to that residual reduction.
    AmgCoarseSolver(dealii::PETScWrappers::MPI::SparseMatrix         &matrix,
                    std::vector<dealii::PETScWrappers::MPI::Vector> rigid_body_modes,
                    unsigned int block_size, double relative_tolerance,
                    const std::string &petsc_options);
    ~AmgCoarseSolver() override;
    AmgCoarseSolver(const AmgCoarseSolver &)            = delete;
    AmgCoarseSolver &operator=(const AmgCoarseSolver &) = delete;

    void operator()(const unsigned int level, VectorType &dst, const VectorType &src) const override;

    // Inner CG iterations over all coarse solves so far.
    unsigned int inner_iterations() const { return total_iterations; }

  private:
    KSP                                        ksp = nullptr;
    mutable dealii::PETScWrappers::MPI::Vector rhs, correction;
    mutable unsigned int                       total_iterations = 0;
  };
} // namespace compliant::fast_solver
