// Generalized symmetric eigenproblem K x = lambda M x for the eigenvalues nearest a shift (the
// lowest natural frequencies, the buckling factors nearest zero): SLEPc Krylov-Schur with
// shift-and-invert, the inverse (K - sigma M)^-1 by MUMPS LU.
#pragma once

#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include <string>
#include <vector>

namespace compliant
{
  struct EigenSettings
  {
    unsigned int n_modes = 6;
    // Spectral shift sigma in (rad/time)^2. Shift-and-invert finds the eigenvalues nearest to it;
    // a negative shift makes K - sigma M definite, so structures with rigid-body modes work.
    double       shift          = 0;
    double       tolerance      = 1e-10;
    unsigned int max_iterations = 1000;
    std::string  petsc_options; // extra -eps_/-st_ options, applied last
    // false: the second matrix is symmetric but indefinite (buckling: K x = lambda (-K_sigma) x),
    // solved as a general problem, and the vectors keep SLEPc's unit 2-norm.
    bool definite_second_matrix = true;
    // Both matrices exactly symmetric: K - sigma M factored by LDL^T; false: LU (a 3D tangent with
    // rigid boundaries is unsymmetric).
    bool symmetric = true;
  };

  struct EigenResult
  {
    std::vector<double>                             eigenvalues;  // omega^2, ascending
    std::vector<dealii::PETScWrappers::MPI::Vector> eigenvectors; // x^T M x = 1
    // ||K x - l M x|| / ((||K|| + |l| ||M||) ||x||): meaningful for l near 0 (rigid-body modes).
    std::vector<double>                             backward_errors;
    unsigned int                                    iterations = 0;
    unsigned int                                    n_converged = 0;
  };

  // K and M must be condensed with the same constraints; constrained rows of M must have a zero
  // diagonal so that they go to infinite eigenvalues. Throws std::runtime_error if fewer than
  // n_modes pairs converge.
  EigenResult solve_eigenproblem(const dealii::PETScWrappers::MPI::SparseMatrix &stiffness,
                                 const dealii::PETScWrappers::MPI::SparseMatrix &mass,
                                 const dealii::IndexSet                         &locally_owned,
                                 const EigenSettings                            &settings);
} // namespace compliant
