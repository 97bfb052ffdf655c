// The Newton tangent of total-Lagrangian finite-strain elasticity applied without a stored matrix,
// as in Davydov et al. (2020), "A matrix-free approach for finite-strain hyperelastic problems
// using geometric multigrid", IJNME 121: at every Gauss point the deformation gradient F, the
// second Piola-Kirchhoff stress S and the material tangent dS/dE of the current state are cached,
// and an increment du acts through
//   dP = Grad du S + F (dS/dE : sym(F^T Grad du)),   (v, du) -> int Grad v : dP dV.
// On a coarser level of the p-multigrid the state is the fine displacement's gradient evaluated
// at that level's own Gauss points: no interpolation, so imposed motions (a turned end) are seen
// on every level exactly. Constrained DoFs act as identity rows, as in ElasticityOperator.
#pragma once

#include <deal.II/base/aligned_vector.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include "fast_solver/matrix_free_operator_base.h"

#include <array>
#include <functional>
#include <vector>

namespace dealii::PETScWrappers::MPI
{
  class Vector;
}

namespace compliant::fast_solver
{
  // The law at one point: S and dS/dE from the displacement gradient (already scaled by the 2D
  // thickness). Non-finite values make set_state throw.
  template <int dim>
  using PointResponse =
    std::function<void(dealii::types::material_id, const dealii::Tensor<2, dim> &grad_u,
                       dealii::SymmetricTensor<2, dim> &S, dealii::SymmetricTensor<4, dim> &dS_dE)>;

  template <int dim, typename Number>
  class TangentOperator : public MatrixFreeOperatorBase<dim, Number>
  {
  public:
    using VectorType = typename MatrixFreeOperatorBase<dim, Number>::VectorType;
    using Vectorized = SimdArray<Number>;

    // constraints must be homogeneous (hanging nodes, supports held at zero). The state starts
    // undeformed and stress-free until set_state. hourglass_stiffness e >= 0 on a level of degree
    // >= 2: (1 - e) times the tangent integrated with p Gauss points per direction plus e times
    // the fully integrated one, as the assembled residual and tangent with
    // discretization/reduced_integration.h's rule; negative or degree 1: p + 1 points.
    void reinit(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints, double hourglass_stiffness = -1);

    // Caches F, S, dS/dE at this operator's Gauss points from the displacement u (ghosted),
    // which lives on state_dofs: the same mesh, any degree. Throws std::runtime_error where the
    // law gives no finite answer (an inverted point).
    void set_state(const dealii::DoFHandler<dim> &state_dofs,
                   const dealii::PETScWrappers::MPI::Vector &u, const PointResponse<dim> &response);

    // The cached state of cell batch `batch` at its Gauss point q.
    struct PointState
    {
      dealii::Tensor<2, dim, Vectorized>          F;
      dealii::SymmetricTensor<2, dim, Vectorized> S;
      dealii::SymmetricTensor<4, dim, Vectorized> dS_dE;
    };

  private:
    void apply_cells(VectorType &dst, const VectorType &src, bool plain) const override;
    void add_kernel_diagonal(VectorType &diagonal) const override;
    // Exact without hanging nodes or ties.
    void add_unconstrained_diagonal(VectorType &diagonal) const override;
    void add_kernel_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix) const override;
    void add_kernel_subspace_matrix(const LongEdgeSpace &space, Mat matrix) const override;

    // The state at rule r's points (0: p + 1 per direction, 1: p with reduced integration):
    // batch * n_q_points[r] + q.
    std::array<unsigned int, 2>                      n_q_points{{1, 0}};
    std::array<dealii::AlignedVector<PointState>, 2> state;
    bool                                             reduced   = false;
    double                                           hourglass = 0; // the full rule's share when reduced
  };
} // namespace compliant::fast_solver
