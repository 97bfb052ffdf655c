// The coarsest level of the p-multigrid, on the assembled degree-1 matrix: either PETSc's
// smoothed-aggregation AMG (GAMG, given the block size and the rigid-body modes), as one V-cycle (a
// fixed linear operator) or as CG preconditioned by it to a relative tolerance (then the outer
// Krylov method must be flexible); or an exact MUMPS factorization, factored once, for thin parts
// where GAMG needs tens of iterations per coarse solve and the degree-1 system is small.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/multigrid/mg_base.h>

#include <petscksp.h>

#include "linear_algebra/direct_factorization.h"

#include <memory>
#include <string>
#include <vector>

namespace compliant::fast_solver
{
  class CoarseLevelSolver : public dealii::MGCoarseGridBase<dealii::LinearAlgebra::distributed::Vector<double>>
  {
  public:
    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    // The matrix must outlive this object. 'Linear solver/PETSc options' apply here too.
    // direct: MUMPS. Otherwise relative_tolerance = 0: one GAMG V-cycle; > 0: CG + GAMG to that
    // residual reduction.
    CoarseLevelSolver(dealii::PETScWrappers::MPI::SparseMatrix         &matrix,
                      std::vector<dealii::PETScWrappers::MPI::Vector> rigid_body_modes,
                      unsigned int block_size, bool direct, double relative_tolerance,
                      const std::string &petsc_options);
    // An existing factor of the same degree-1 system (a degree-1 model solved by MUMPS), kept
    // alive here; owned: its rows on this rank.
    CoarseLevelSolver(std::shared_ptr<const DirectFactorization> factor, const dealii::IndexSet &owned,
                      MPI_Comm communicator);
    // A preconditioner already set up on the same degree-1 system (a degree-1 model solved by CG +
    // GAMG): this object takes over the caller's reference. relative_tolerance as above.
    CoarseLevelSolver(PC set_up_preconditioner, const dealii::IndexSet &owned, double relative_tolerance,
                      MPI_Comm communicator);
    ~CoarseLevelSolver() override;
    CoarseLevelSolver(const CoarseLevelSolver &)            = delete;
    CoarseLevelSolver &operator=(const CoarseLevelSolver &) = delete;

    void operator()(const unsigned int level, VectorType &dst, const VectorType &src) const override;

    // Inner CG iterations over all coarse solves so far (direct: the number of solves).
    unsigned int inner_iterations() const { return total_iterations; }

  private:
    KSP                                        ksp = nullptr;
    std::shared_ptr<const DirectFactorization> factor; // instead of ksp
    mutable dealii::PETScWrappers::MPI::Vector rhs, correction;
    mutable unsigned int                       total_iterations = 0;
  };

  // The degree-1 level as a whole: its matrix (empty where the solver came from another model's
  // factor or preconditioner), its solver, and a fingerprint of its DoFs (sums of
  // the owned DoFs' indices times their vertices' coordinates). Kept after a solve, it serves a
  // second solver on the same mesh numbered the same way (the error estimates' degree-(p+1)
  // model), which then skips the degree-1 matrix and the AMG set-up.
  struct DegreeOneLevel
  {
    dealii::PETScWrappers::MPI::SparseMatrix matrix;
    std::unique_ptr<CoarseLevelSolver>       solver;
    std::vector<double>                      fingerprint;
    dealii::IndexSet                         owned; // the degree-1 DoFs of this rank
    bool                                     direct = false;
    // The degree-1 DoFs it was built on, and their constraints held at zero, where the model
    // that built it keeps them (a degree-1 model): a degree-2 solver on a twin mesh takes them
    // as its degree-1 level instead of distributing its own. The model must outlive the solvers
    // built on them (the error estimates' enriched model lives inside the model's run).
    const dealii::DoFHandler<2>      *dofs_2d = nullptr;
    const dealii::DoFHandler<3>      *dofs_3d = nullptr;
    dealii::AffineConstraints<double> constraints;
    template <int dim>
    const dealii::DoFHandler<dim> *dofs() const
    {
      if constexpr (dim == 2)
        return dofs_2d;
      else
        return dofs_3d;
    }
  };

  // Sums over the owned DoFs of (index + 1) times each coordinate of the DoF's vertex, and the
  // DoF count: equal on two degree-1 DoFHandlers exactly when they number the same vertices alike.
  template <int dim>
  std::vector<double> degree_one_fingerprint(const dealii::DoFHandler<dim> &dofs, MPI_Comm communicator);

  // The degree-1 level of a degree-1 model solved by MUMPS: its matrix's factor serves as the
  // exact coarse solve of the degree-2 model on the same mesh (the error estimates' enriched one).
  // held_at_zero: the model's constraints without their values.
  template <int dim>
  std::shared_ptr<DegreeOneLevel> degree_one_level_from_factor(const dealii::DoFHandler<dim>             &dofs,
                                                               const dealii::AffineConstraints<double>   &held_at_zero,
                                                               std::shared_ptr<const DirectFactorization> factor,
                                                               MPI_Comm communicator);

  // The degree-1 level of a degree-1 model solved by CG + GAMG: its set-up GAMG (the reference is
  // taken over) serves the degree-2 model on the same mesh, by CG to relative_tolerance.
  template <int dim>
  std::shared_ptr<DegreeOneLevel> degree_one_level_from_preconditioner(const dealii::DoFHandler<dim> &dofs,
                                                                       const dealii::AffineConstraints<double> &held_at_zero,
                                                                       PC set_up_preconditioner,
                                                                       double relative_tolerance,
                                                                       MPI_Comm communicator);

  // Whether `level` (kept from another solver) serves these degree-1 DoFs: the same numbering
  // and, on every rank, the same owned DoFs.
  template <int dim>
  bool degree_one_level_fits(const DegreeOneLevel &level, const dealii::DoFHandler<dim> &dofs,
                             const std::vector<double> &fingerprint, MPI_Comm communicator);
} // namespace compliant::fast_solver
