// Small-strain isotropic elasticity applied without a stored matrix: sum factorization on
// quadrilaterals/hexahedra (deal.II MatrixFree), the operator on every level of the p-multigrid.
// Lame parameters are per cell, from its material id; constrained DoFs act as identity rows.
#pragma once

#include <deal.II/base/subscriptor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <functional>
#include <memory>
#include <utility>
#include <vector>

namespace dealii::PETScWrappers::MPI
{
  class SparseMatrix;
}

namespace compliant::fast_solver
{
  // (lambda, mu) of a material id, already scaled by the 2D thickness and reduced for plane stress.
  using LameParameters = std::function<std::pair<double, double>(dealii::types::material_id)>;

  template <int dim, typename Number>
  class ElasticityOperator : public dealii::Subscriptor
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<Number>;
    using value_type = Number;

    // constraints must be homogeneous (hanging nodes, zero supports): the operator acts on
    // the correction from a lifting that carries the prescribed values.
    void reinit(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                const dealii::AffineConstraints<Number> &constraints, const LameParameters &lame);

    void vmult(VectorType &dst, const VectorType &src) const;
    void Tvmult(VectorType &dst, const VectorType &src) const { vmult(dst, src); }
    void vmult_add(VectorType &dst, const VectorType &src) const;
    void Tvmult_add(VectorType &dst, const VectorType &src) const { vmult_add(dst, src); }

    // dst = C^T (A src) with src read as given at constrained DoFs (no constraint resolution):
    // moves prescribed values to the right-hand side.
    void apply_to_lifting(VectorType &dst, const VectorType &src) const;

    void initialize_dof_vector(VectorType &vector) const;
    void compute_inverse_diagonal(VectorType &inverse_diagonal) const;
    // The assembled matrix with unit diagonal on constrained rows (for the coarse AMG).
    void compute_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix, MPI_Comm communicator) const;

    dealii::types::global_dof_index m() const;
    dealii::types::global_dof_index n() const { return m(); }
    Number el(const unsigned int, const unsigned int) const; // not available: asserts

    const dealii::MatrixFree<dim, Number> &matrix_free() const { return *data; }
    unsigned int                           degree() const { return fe_degree; }

  private:
    void apply_cells(VectorType &dst, const VectorType &src, bool plain) const;
    // The diagonal from shape-function gradients alone (no sum-factorized unit vectors): exact
    // when no constraint has entries (no hanging nodes, no ties), which is the common case.
    void add_unconstrained_diagonal(VectorType &diagonal) const;

    std::shared_ptr<dealii::MatrixFree<dim, Number>> data;
    const dealii::AffineConstraints<Number>         *constraints = nullptr;
    const dealii::Mapping<dim>                      *mapping     = nullptr;
    bool                                             constraints_have_entries = false;
    unsigned int                                     fe_degree   = 1;
    // Per cell batch: the Lame parameters of each lane's cell.
    std::vector<dealii::VectorizedArray<Number>> lambda, mu;
    std::vector<unsigned int>                    constrained_local_dofs;
  };
} // namespace compliant::fast_solver
