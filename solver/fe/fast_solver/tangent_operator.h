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
#include <deal.II/base/subscriptor.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <functional>
#include <memory>
#include <vector>

namespace dealii::PETScWrappers::MPI
{
  class SparseMatrix;
  class Vector;
} // namespace dealii::PETScWrappers::MPI

namespace compliant::fast_solver
{
  // The law at one point: S and dS/dE from the displacement gradient (already scaled by the 2D
  // thickness). Non-finite values make set_state throw.
  template <int dim>
  using PointResponse =
    std::function<void(dealii::types::material_id, const dealii::Tensor<2, dim> &grad_u,
                       dealii::SymmetricTensor<2, dim> &S, dealii::SymmetricTensor<4, dim> &dS_dE)>;

  template <int dim, typename Number>
  class TangentOperator : public dealii::Subscriptor
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<Number>;
    using value_type = Number;
    using Vectorized = dealii::VectorizedArray<Number>;

    // constraints must be homogeneous (hanging nodes, supports held at zero). The state starts
    // undeformed and stress-free until set_state.
    void reinit(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints);

    // Caches F, S, dS/dE at this operator's Gauss points from the displacement u (ghosted),
    // which lives on state_dofs: the same mesh, any degree. Throws std::runtime_error where the
    // law gives no finite answer (an inverted point).
    void set_state(const dealii::DoFHandler<dim> &state_dofs,
                   const dealii::PETScWrappers::MPI::Vector &u, const PointResponse<dim> &response);

    void vmult(VectorType &dst, const VectorType &src) const;
    void Tvmult(VectorType &dst, const VectorType &src) const { vmult(dst, src); }
    void vmult_add(VectorType &dst, const VectorType &src) const;
    void Tvmult_add(VectorType &dst, const VectorType &src) const { vmult_add(dst, src); }
    // dst = C^T (A src) with src read as given at constrained DoFs (moves prescribed values to
    // the right-hand side).
    void apply_to_lifting(VectorType &dst, const VectorType &src) const;

    void initialize_dof_vector(VectorType &vector) const;
    void compute_inverse_diagonal(VectorType &inverse_diagonal) const;
    // The assembled matrix with unit diagonal on constrained rows (for the coarse level).
    void compute_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix, MPI_Comm communicator) const;

    dealii::types::global_dof_index m() const;
    dealii::types::global_dof_index n() const { return m(); }
    Number el(const unsigned int, const unsigned int) const; // not available: throws

    const dealii::MatrixFree<dim, Number> &matrix_free() const { return *data; }
    unsigned int                           degree() const { return fe_degree; }

    // The cached state of cell batch `batch` at its Gauss point q.
    struct PointState
    {
      dealii::Tensor<2, dim, Vectorized>          F;
      dealii::SymmetricTensor<2, dim, Vectorized> S;
      dealii::SymmetricTensor<4, dim, Vectorized> dS_dE;
    };

  private:
    void apply_cells(VectorType &dst, const VectorType &src, bool plain) const;
    // The diagonal from shape-function gradients (exact without hanging nodes or ties).
    void add_unconstrained_diagonal(VectorType &diagonal) const;

    std::shared_ptr<dealii::MatrixFree<dim, Number>> data;
    const dealii::AffineConstraints<Number>         *constraints = nullptr;
    const dealii::Mapping<dim>                      *mapping     = nullptr;
    bool                                             constraints_have_entries = false;
    unsigned int                                     fe_degree   = 1;
    unsigned int                                     n_q_points  = 1;
    dealii::AlignedVector<PointState>                state; // batch * n_q_points + q
    std::vector<unsigned int>                        constrained_local_dofs;
  };
} // namespace compliant::fast_solver
