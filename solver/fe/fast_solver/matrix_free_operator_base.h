// What the two matrix-free operators (small-strain ElasticityOperator, finite-strain
// TangentOperator) share: the MatrixFree set-up, identity rows on constrained DoFs, the lifting
// product, the inverse diagonal and the assembled coarse matrix. A derived operator supplies only
// its cell kernel (apply_cells) and its diagonal and matrix from that kernel.
#pragma once

#include "fast_solver/simd.h"

#include <deal.II/base/subscriptor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/matrix_free/matrix_free.h>

#include <petscmat.h>

#include <memory>
#include <vector>

namespace dealii::PETScWrappers::MPI
{
  class SparseMatrix;
}

namespace compliant::fast_solver
{
  struct LongEdgeSpace; // fast_solver/long_edge_space.h

  // Whether any constraint on any rank has entries (hanging nodes, ties), not only fixed values.
  template <typename Number>
  bool constraints_have_entries(const dealii::AffineConstraints<Number> &constraints, MPI_Comm communicator);

  template <int dim, typename Number>
  class MatrixFreeOperatorBase : public dealii::Subscriptor
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<Number>;
    using value_type = Number;

    virtual ~MatrixFreeOperatorBase() = default;

    void vmult(VectorType &dst, const VectorType &src) const;
    void Tvmult(VectorType &dst, const VectorType &src) const { vmult(dst, src); }
    void vmult_add(VectorType &dst, const VectorType &src) const;
    void Tvmult_add(VectorType &dst, const VectorType &src) const { vmult_add(dst, src); }

    // dst = C^T (A src) with src read as given at constrained DoFs (no constraint resolution):
    // moves prescribed values to the right-hand side.
    void apply_to_lifting(VectorType &dst, const VectorType &src) const;

    void initialize_dof_vector(VectorType &vector) const;
    // The DoF layout alone (initialize_dof_vector), no geometry: for a level that is never
    // applied (the p-multigrid's degree-1 level when another solver's coarse solve serves it).
    void reinit_layout(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                       const dealii::AffineConstraints<Number> &constraints);
    // Non-positive entries (a tangent past a limit point) are left unscaled.
    void compute_inverse_diagonal(VectorType &inverse_diagonal) const;
    // The assembled matrix with unit diagonal on constrained rows (for the coarse level).
    void compute_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix, MPI_Comm communicator) const;

    // Adds the Galerkin matrix P^T K P of the long-edge space (degree 2 only) to `matrix`, laid
    // out in the space's coarse numbering; the caller assembles it.
    virtual void add_kernel_subspace_matrix(const LongEdgeSpace &space, Mat matrix) const = 0;

    dealii::types::global_dof_index m() const;
    dealii::types::global_dof_index n() const { return m(); }
    Number el(const unsigned int, const unsigned int) const; // not available: throws

    const dealii::MatrixFree<dim, Number, SimdArray<Number>> &matrix_free() const { return *data; }
    unsigned int                           degree() const { return fe_degree; }
    // Whether the kernel also has the reduced rule (Discretization/Integration = reduced), whose
    // soft hourglass modes the smoother has to reach.
    bool has_reduced_quadrature() const { return reduced_quadrature; }

  protected:
    // constraints must be homogeneous (hanging nodes, supports held at zero): the operator acts
    // on the correction from a lifting that carries the prescribed values.
    // with_reduced_quadrature: a second rule (index 1) of p Gauss points per direction beside the
    // p + 1 of rule 0 (Discretization/Integration = reduced).
    void reinit_matrix_free(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &dof_handler,
                            const dealii::AffineConstraints<Number> &constraints,
                            bool with_reduced_quadrature = false);

    // dst = A src cell by cell, src read with (plain = false) or without constraint resolution.
    virtual void apply_cells(VectorType &dst, const VectorType &src, bool plain) const = 0;
    // The diagonal through the kernel on unit vectors (needed where constraints have entries).
    virtual void add_kernel_diagonal(VectorType &diagonal) const = 0;
    // The diagonal from shape-function gradients alone: exact when no constraint has entries
    // (no hanging nodes, no ties), the common case, and much cheaper.
    virtual void add_unconstrained_diagonal(VectorType &diagonal) const = 0;
    // The cell matrices through the kernel, into the matrix laid out by compute_matrix.
    virtual void add_kernel_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix) const = 0;

    std::shared_ptr<dealii::MatrixFree<dim, Number, SimdArray<Number>>> data;
    const dealii::AffineConstraints<Number>         *constraints = nullptr;
    const dealii::Mapping<dim>                      *mapping     = nullptr;
    bool                                             constraints_have_entries = false;
    unsigned int                                     fe_degree   = 1;
    bool                                             reduced_quadrature = false;

  private:
    std::vector<unsigned int> constrained_local_dofs;
  };
} // namespace compliant::fast_solver
