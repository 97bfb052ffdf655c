#include "analyses/modal_eigensolver.h"
#include "linear_algebra/petsc_check.h"

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    const PetscErrorCheck check("modal analysis (SLEPc)");

    // Owns the EPS so that every exit path destroys it.
    struct EpsHandle
    {
      EPS eps = nullptr;
      ~EpsHandle()
      {
        if (eps)
          EPSDestroy(&eps);
      }
    };
  } // namespace

  EigenResult solve_eigenproblem(const dealii::PETScWrappers::MPI::SparseMatrix &stiffness,
                                 const dealii::PETScWrappers::MPI::SparseMatrix &mass,
                                 const dealii::IndexSet                         &locally_owned,
                                 const EigenSettings                            &settings)
  {
    MPI_Comm  comm = stiffness.get_mpi_communicator();
    EpsHandle handle;
    EPS      &eps = handle.eps;
    check(EPSCreate(comm, &eps), "EPSCreate");
    check(EPSSetOperators(eps, stiffness, mass), "EPSSetOperators");
    // Symmetric K, symmetric positive semi-definite M (zero on constrained rows).
    check(EPSSetProblemType(eps, settings.definite_second_matrix ? EPS_GHEP : EPS_GNHEP), "EPSSetProblemType");
    check(EPSSetType(eps, EPSKRYLOVSCHUR), "EPSSetType");
    check(EPSSetDimensions(eps, settings.n_modes, PETSC_DEFAULT, PETSC_DEFAULT),
          "EPSSetDimensions");
    check(EPSSetTolerances(eps, settings.tolerance, settings.max_iterations), "EPSSetTolerances");
    // Shift-and-invert: nu = 1 / (lambda - sigma), the wanted eigenvalues nearest sigma become the
    // largest nu (SLEPc users manual, sec. 3.3.3).
    check(EPSSetWhichEigenpairs(eps, EPS_TARGET_MAGNITUDE), "EPSSetWhichEigenpairs");
    check(EPSSetTarget(eps, settings.shift), "EPSSetTarget");
    ST  st;
    KSP ksp;
    PC  pc;
    check(EPSGetST(eps, &st), "EPSGetST");
    check(STSetType(st, STSINVERT), "STSetType");
    check(STGetKSP(st, &ksp), "STGetKSP");
    check(KSPSetType(ksp, KSPPREONLY), "KSPSetType");
    check(KSPGetPC(ksp, &pc), "KSPGetPC");
    // K - sigma M is symmetric: MUMPS LDL^T, half the flops and memory of LU.
    if (settings.symmetric)
      {
        check(MatSetOption(static_cast<Mat>(stiffness), MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(symmetric)");
        check(MatSetOption(static_cast<Mat>(mass), MAT_SYMMETRIC, PETSC_TRUE), "MatSetOption(symmetric)");
      }
    check(PCSetType(pc, settings.symmetric ? PCCHOLESKY : PCLU), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType(mumps)");
    if (!settings.petsc_options.empty())
      check(PetscOptionsInsertString(nullptr, settings.petsc_options.c_str()),
            "PetscOptionsInsertString (Linear solver/PETSc options)");
    check(EPSSetFromOptions(eps), "EPSSetFromOptions");
    check(EPSSolve(eps), "EPSSolve");

    PetscInt n_converged, iterations;
    check(EPSGetConverged(eps, &n_converged), "EPSGetConverged");
    check(EPSGetIterationNumber(eps, &iterations), "EPSGetIterationNumber");
    if (n_converged < static_cast<PetscInt>(settings.n_modes))
      throw std::runtime_error("eigensolver: only " + std::to_string(n_converged) + " of " +
                               std::to_string(settings.n_modes) + " eigenpairs converged in " +
                               std::to_string(iterations) +
                               " restarts; raise the analysis' Maximum iterations or relax its Tolerance");

    // SLEPc orders by distance to the target; keep the n nearest, then sort ascending.
    std::vector<double>                             values(settings.n_modes);
    std::vector<double>                             errors(settings.n_modes);
    std::vector<dealii::PETScWrappers::MPI::Vector> vectors;
    dealii::PETScWrappers::MPI::Vector              m_x(locally_owned, comm);
    for (unsigned int i = 0; i < settings.n_modes; ++i)
      {
        vectors.emplace_back(locally_owned, comm);
        PetscScalar real_part, imaginary_part;
        check(EPSGetEigenpair(eps, i, &real_part, &imaginary_part, vectors.back(), nullptr),
              "EPSGetEigenpair");
        check(EPSComputeError(eps, i, EPS_ERROR_BACKWARD, &errors[i]), "EPSComputeError");
        values[i] = real_part;
        if (settings.definite_second_matrix)
          {
            mass.vmult(m_x, vectors.back());
            vectors.back() /= std::sqrt(vectors.back() * m_x); // mass-normalized
          }
      }
    std::vector<unsigned int> order(settings.n_modes);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](unsigned a, unsigned b) { return values[a] < values[b]; });

    EigenResult result;
    result.iterations  = iterations;
    result.n_converged = n_converged;
    for (const unsigned int i : order)
      {
        result.eigenvalues.push_back(values[i]);
        result.backward_errors.push_back(errors[i]);
        result.eigenvectors.push_back(std::move(vectors[i]));
      }
    return result;
  }
} // namespace compliant
