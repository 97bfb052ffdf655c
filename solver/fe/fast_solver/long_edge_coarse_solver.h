// The coarse solve of a p-multigrid whose lowest level is degree 2 on long cells: smoothing on
// that level, the exact correction in the long-edge space (fast_solver/long_edge_space.h, its
// Galerkin matrix factored by MUMPS), smoothing again. The long-edge space holds the bending
// modes that the degree-1 level locks on, so the smoother needs no wide eigenvalue range.
#pragma once

#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/multigrid/mg_base.h>

#include <petscksp.h>

#include "fast_solver/long_edge_space.h"
#include "fast_solver/matrix_free_operator_base.h"

#include <memory>

namespace compliant::fast_solver
{
  template <int dim>
  class LongEdgeCoarseSolver : public dealii::MGCoarseGridBase<dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    // level_operator (degree 2), smoother (its level's) and space must outlive this object.
    // Assembles the Galerkin matrix from the operator's kernel and factors it; throws
    // std::runtime_error if PETSc fails.
    LongEdgeCoarseSolver(const MatrixFreeOperatorBase<dim, double> &level_operator,
                         const dealii::MGSmootherBase<VectorType>  &smoother,
                         std::shared_ptr<const LongEdgeSpace> space, MPI_Comm communicator);
    ~LongEdgeCoarseSolver() override;
    LongEdgeCoarseSolver(const LongEdgeCoarseSolver &)            = delete;
    LongEdgeCoarseSolver &operator=(const LongEdgeCoarseSolver &) = delete;

    // Assembles and factors again after the operator changed (a new Newton state); the pattern
    // and MUMPS's analysis are kept.
    void refactor();

    void operator()(const unsigned int level, VectorType &dst, const VectorType &src) const override;

    // Coarse solves so far.
    unsigned int solves() const { return n_solves; }
    dealii::types::global_dof_index size() const { return space->n_coarse; }

  private:
    void assemble();
    void release(); // every PETSc object (null ones skipped)

    const MatrixFreeOperatorBase<dim, double> &level_operator;
    const dealii::MGSmootherBase<VectorType>  &smoother;
    std::shared_ptr<const LongEdgeSpace>       space;
    MPI_Comm                                   communicator;
    Mat                                        matrix = nullptr; // the Galerkin matrix
    KSP                                        ksp    = nullptr;
    Vec                                        rhs = nullptr, solution = nullptr, wrapped = nullptr;
    mutable VectorType                         residual;
    mutable unsigned int                       n_solves = 0;
  };
} // namespace compliant::fast_solver
