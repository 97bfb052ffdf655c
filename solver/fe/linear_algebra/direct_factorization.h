// A sparse direct factorization (MUMPS through PETSc) kept for several right-hand sides: arc-length
// continuation solves the tangent for the residual and for the load pattern with one factor. The
// LDL^T factor of a symmetric matrix also gives its inertia (Sylvester's law), the count of
// negative eigenvalues that tells a stable equilibrium from an unstable one.
#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <petscksp.h>

namespace compliant
{
  class DirectFactorization
  {
  public:
    DirectFactorization() = default;
    DirectFactorization(const DirectFactorization &) = delete;
    DirectFactorization &operator=(const DirectFactorization &) = delete;
    ~DirectFactorization();

    // Factors the matrix: LDL^T if symmetric, LU otherwise. The matrix must outlive the solves.
    // Throws std::runtime_error if PETSc fails.
    // with_options: 'Linear solver/PETSc options' (inserted by the caller) apply to the solver.
    // inertia (symmetric only): count the negative eigenvalues, with MUMPS's null-pivot detection
    // and without ScaLAPACK at the root (ICNTL 13, 24); a plain solve leaves both off.
    // Called again on the same matrix object with the same kind (with_options is taken from the
    // first call), the factorization keeps MUMPS's
    // analysis (ordering, symbolic factors) while the sparsity pattern is unchanged: PETSc redoes
    // the numerical factorization alone, as a Newton iteration needs.
    void factor(dealii::PETScWrappers::MPI::SparseMatrix &matrix, bool symmetric, bool with_options = false,
                bool inertia = true);
    void solve(dealii::PETScWrappers::MPI::Vector &x, const dealii::PETScWrappers::MPI::Vector &b) const;
    // The same on bare PETSc vectors (a preconditioner's coarse level); x and b distinct.
    void solve(Vec x, Vec b) const;
    // x = A^-T b from the same factors (an adjoint: the dual of an unsymmetric tangent).
    void solve_transpose(dealii::PETScWrappers::MPI::Vector &x, const dealii::PETScWrappers::MPI::Vector &b) const;
    // Negative eigenvalues of the factored matrix; only for a symmetric one factored with inertia.
    unsigned int negative_eigenvalues() const;

  private:
    // One attempt: the reduced PETSc failure reason, 0 on success; throws on a PETSc error code.
    int  factor_once(dealii::PETScWrappers::MPI::SparseMatrix &matrix, bool symmetric, bool with_options, bool inertia);
    KSP  ksp       = nullptr;
    Mat  factored  = nullptr; // the matrix of the kept analysis
    bool symmetric = false, with_inertia = false;
  };
} // namespace compliant
