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
    void reinit(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints, const LameParameters &lame);

  private:
    void apply_cells(VectorType &dst, const VectorType &src, bool plain) const override;
    void add_kernel_diagonal(VectorType &diagonal) const override;
    void add_unconstrained_diagonal(VectorType &diagonal) const override;
    void add_kernel_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix) const override;

    // Per cell batch: the Lame parameters of each lane's cell.
    std::vector<dealii::VectorizedArray<Number>> lambda, mu;
  };
} // namespace compliant::fast_solver
