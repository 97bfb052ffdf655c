// Small-strain isotropic elasticity applied without a stored matrix: sum factorization on
// quadrilaterals/hexahedra (deal.II MatrixFree), the operator on every level of the p-multigrid.
// Lame parameters are per cell, from its material id; constrained DoFs act as identity rows.
#pragma once

#include "fast_solver/matrix_free_operator_base.h"

#include <functional>
#include <utility>
#include <vector>

namespace compliant::fast_solver
{
  // (lambda, mu) of a material id, already scaled by the 2D thickness and reduced for plane stress.
  using LameParameters = std::function<std::pair<double, double>(dealii::types::material_id)>;

  template <int dim, typename Number>
  class ElasticityOperator : public MatrixFreeOperatorBase<dim, Number>
  {
  public:
    using VectorType = typename MatrixFreeOperatorBase<dim, Number>::VectorType;

    // constraints must be homogeneous (hanging nodes, zero supports): the operator acts on
    // the correction from a lifting that carries the prescribed values.
    // hourglass_stiffness >= 0 on a level of degree >= 2: the stiffness integrated with p Gauss
    // points per direction, plus that fraction of the fully integrated one
    // (discretization/reduced_integration.h); negative or degree 1: p + 1 points.
    void reinit(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints, const LameParameters &lame,
                double hourglass_stiffness = -1);

  private:
    void apply_cells(VectorType &dst, const VectorType &src, bool plain) const override;
    void add_kernel_diagonal(VectorType &diagonal) const override;
    void add_unconstrained_diagonal(VectorType &diagonal) const override;
    void add_kernel_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix) const override;
    void add_kernel_subspace_matrix(const LongEdgeSpace &space, Mat matrix) const override;

    // Per cell batch: the Lame parameters of each lane's cell.
    std::vector<SimdArray<Number>> lambda, mu;
    bool   reduced = false;
    double hourglass = 0; // the fully integrated share e when reduced

  };
} // namespace compliant::fast_solver
