// The fast linear solver for elasticity on quadrilaterals/hexahedra: conjugate gradients on a
// matrix-free operator (small-strain ElasticityOperator, or the finite-strain TangentOperator of a
// Newton step), preconditioned by a p-multigrid V-cycle (degree p, p-1, ..., 1 on the same
// mesh, Chebyshev smoothing on the diagonal) whose degree-1 level is solved by AMG (PETSc GAMG with
// block size and rigid-body modes) or, for thin parts, by MUMPS. Only the degree-1 matrix is
// ever stored.
//
// Long cells (a thin leaf meshed 8 : 1 : 1) leave error modes along the long direction that the
// diagonal sees as nearly converged: the smoother then damps a wider eigenvalue range with a
// higher polynomial, both from the largest cell aspect ratio a (range 3 a^2, degree ~ sqrt of
// range, 4 to 16), and the degree-1 level, where GAMG needs tens of iterations on such meshes, is
// factored by MUMPS while it is small. Measured on cases/benchmarks/leaf_torsion.prm (90k DoFs,
// a = 8): fixed degree 4 / range 20 with GAMG took 91 iterations and 6.8 s, the sized smoother
// with MUMPS 30 iterations and 2.7 s.
//
// Those modes are bending along the long cells, which degree 1 locks on: Q1 is the Galerkin
// coarse space of Q2, but it does not contain them. Where cells are long (a > 3), the level below
// degree 2 is therefore the long-edge space instead (fast_solver/long_edge_space.h: quadratic
// along each cell's long edges, linear across, factored by MUMPS), which does; the smoother keeps
// the degree and range of cubes (4 over 20). Torsion bar on 12:1 cells, 63k DoFs: 12 iterations and
// 0.50 s of solve against the sized smoother's 34 and 1.08 s (cases/benchmarks/long_edge_speed.md).
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/petsc_vector.h>

#include <deal.II/lac/petsc_sparse_matrix.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace compliant::fast_solver
{
  struct DegreeOneLevel; // fast_solver/coarse_level_solver.h

  struct PMultigridSettings
  {
    double       relative_tolerance = 1e-10;
    unsigned int max_iterations     = 500;
    // Measured on the 140k-DoF Q2 cantilever (cases/benchmarks): degree 4 with an inner coarse
    // tolerance of 0.03 gave 11 outer iterations, the least time; one V-cycle alone gave 34.
    // 0 (default): chosen from the cells' aspect ratio, degree 4 and range 20 for cubes.
    unsigned int smoothing_degree   = 0;  // Chebyshev polynomial degree per smoothing step
    double       smoothing_range    = 0;  // eigenvalue range Chebyshev damps
    // Degree-1 level: automatic = MUMPS for long cells (aspect ratio > 3) while the degree-1
    // system has at most direct_coarse_limit (2D) or direct_coarse_limit_3d DoFs, else AMG.
    // A 3D factorization grows much faster than N, but GAMG on long cells needs tens of inner
    // iterations. With OpenBLAS and LDL^T (2 ranks), MUMPS factors 3D degree-1 levels of 63k,
    // 112k and 203k DoFs in 0.98, 2.65 and 6.1 s (480, 794 and 1404 MB per rank); the 12:1
    // torsion bar at 468k DoFs (63k degree-1) solved in 5.4 s against GAMG's 21.0 s (88 inner
    // iterations per V-cycle), the 10:1 blade hinge at 581k (78k) in 4.4 s against 4.8 s.
    // (With the reference BLAS and LU, the hinge's factorization took 11.6 s: the old limit 50k.)
    enum class Coarse { automatic, amg, direct } coarse = Coarse::automatic;
    double       direct_coarse_limit    = 250000;
    double       direct_coarse_limit_3d = 150000;
    // Long cells (aspect ratio > long_edge_aspect_ratio), all in thin parts (long_cells.h),
    // degree >= 2, coarse level not amg, no hanging nodes: below the degree-2 level the long-edge
    // space (fast_solver/long_edge_space.h) replaces the degree-1 level, factored by MUMPS while
    // within the limits above, and the smoother keeps the degree and range of cubes. On the 12:1
    // torsion bar (63k DoFs) the outer iterations went from 34 (degree 1 factored, Chebyshev 16
    // over 400) to 12 (4 over 20). Reduced integration leaves soft hourglass modes outside the
    // space: a wider range. On the 63k bar, the plate and the leaf, 4 over 20 took 38, 24, 27
    // iterations, 12 over 150 14, 9, 10 and 5-17 % less time.
    bool         long_edge_space              = true;
    double       long_edge_aspect_ratio       = 3;
    // A long cell in a part more than this many times as thick across it as it is long (a block
    // meshed in slabs) is not thin, and then the degree-1 level is used: on the graded blade hinge
    // the space took 36 iterations and 10-30 % more time than the degree-1 level's 20.
    double       long_edge_slenderness        = 2;
    unsigned int long_edge_smoothing_degree   = 4;
    double       long_edge_smoothing_range    = 20;
    unsigned int long_edge_reduced_smoothing_degree = 12;
    double       long_edge_reduced_smoothing_range  = 150;
    double       long_edge_factor_bytes_per_dof = 28e3;
    // AMG: 0 = one V-cycle; > 0 = CG + AMG to this residual reduction, and the outer CG becomes
    // flexible (the preconditioner then varies from one application to the next).
    double       coarse_tolerance   = 0.03;
    // The same for a degree-1 level kept for a warm-started solve (the error estimates' enriched
    // model over a degree-1 model's GAMG): that solve reduces its residual by 1e-4 in about three
    // V-cycles, and a looser inner solve keeps them at three. Lame cylinder, Q1 128 x 256, 2 ranks:
    // 0.03, 0.1, 0.3 gave 3 V-cycles and enriched solves of 0.203, 0.192, 0.187 s (one V-cycle,
    // 0: 4 and 0.207 s), estimates equal to 0.14 %.
    double       warm_start_coarse_tolerance = 0.3;
    // CG iterations that estimate each level's largest eigenvalue for Chebyshev. A warm-started
    // solve (a few iterations) takes 8: on the error estimates' enriched models 15 and 8 gave the
    // same iterations and estimates, 8 saved 0.02 s of 0.24 s (3D Q3, 137k DoFs).
    unsigned int eigenvalue_iterations = 15;
    std::string  petsc_options;           // passed to the coarse GAMG
    // Level transfers: false takes deal.II's on every level (fast_solver/level_transfer.h).
    bool         cell_wise_transfer = true;
    // Another solver's degree-1 level on the same mesh: used instead of building one when its
    // DoFs' fingerprint matches this mesh's (else built as usual, and statistics say so).
    std::shared_ptr<DegreeOneLevel> reused_degree_one_level;
  };

  // A solve that starts from a guess close to the answer (the degree-p solution carried to
  // degree p + 1) and stops when the residual has dropped by `reduction` from the guess's own,
  // not from the right-hand side's: what is left to find is the small difference.
  struct WarmStart
  {
    const dealii::PETScWrappers::MPI::Vector &guess; // owned DoFs, prescribed values included
    double                                    reduction;
  };

  struct PMultigridStatistics
  {
    unsigned int                         iterations    = 0;
    unsigned int                         coarse_iterations = 0; // inner CG, summed
    double                               lifted_rhs_norm   = 0; // |f - K g| of the last solve
    double                               initial_residual  = 0; // |f - K u0|, u0 the start
    double                               setup_seconds = 0;
    double                               largest_aspect_ratio = 1;
    unsigned int                         smoothing_degree = 0;
    double                               smoothing_range  = 0;
    bool                                 coarse_direct    = false;
    bool                                 coarse_reused    = false; // settings' degree-1 level used
    bool                                 lower_reused     = false; // a degree-p solver's V-cycle below
    dealii::types::global_dof_index      long_edge_dofs   = 0;     // the long-edge space's, 0 if not used
    // Long cells lay in thick parts, so the degree-1 level stayed: the largest ratio of a cell's
    // direction left linear to its shortest (0: not so).
    double                               thick_part_aspect_ratio = 0;
    std::vector<dealii::types::global_dof_index> level_dofs; // coarse to fine
  };

  // The lowest level in words, for the log: "degree-1 level by MUMPS" or "... GAMG", or
  // "long-edge space (N DoFs) by MUMPS".
  std::string coarse_level_note(const PMultigridStatistics &statistics);

  // Operator: ElasticityOperator<dim, double> or TangentOperator<dim, double> (instantiated in
  // p_multigrid_solver.cc and p_multigrid_tangent.cc).
  template <int dim, typename Operator>
  class PMultigridSolver
  {
  public:
    // Fills the homogeneous constraints of a level (hanging nodes, supports held at zero) with
    // their index set (the level's locally relevant DoFs); the object comes empty and is closed
    // by the caller.
    using LevelConstraints =
      std::function<void(const dealii::DoFHandler<dim> &, dealii::AffineConstraints<double> &)>;
    // Sets up a level's operator (reinit with the problem's coefficients or state).
    using LevelSetup =
      std::function<void(Operator &, const dealii::Mapping<dim> &, const dealii::DoFHandler<dim> &,
                         const dealii::AffineConstraints<double> &)>;

    using VectorType = dealii::LinearAlgebra::distributed::Vector<double>;

    // Builds every level and the preconditioner; the mapping and fine DoFHandler must outlive
    // the solver. lower: a solver one degree lower on the same mesh, numbered alike (the error
    // estimates' degree-p model for its degree-(p+1) twin). Its whole V-cycle then is this
    // solver's coarse solve, and only the finest level is built here: the levels below, their
    // transfers, smoothers and degree-1 solver are the lower solver's. It is held here and not
    // changed; its DoFHandler, mapping and mesh must outlive this solver. A lower solver that
    // does not fit (statistics say so) is ignored.
    PMultigridSolver(const dealii::Mapping<dim> &mapping, const dealii::DoFHandler<dim> &fine_dofs,
                     const LevelConstraints &level_constraints, const LevelSetup &level_setup,
                     const PMultigridSettings &settings, MPI_Comm communicator,
                     std::shared_ptr<const PMultigridSolver> lower = nullptr);
    ~PMultigridSolver();

    // Changes every level's operator (a new Newton state) and rebuilds what depends on it:
    // diagonals, Chebyshev eigenvalue estimates, the degree-1 matrix and its solver. The mesh,
    // DoFs, constraints and transfers stay.
    void update(const std::function<void(Operator &)> &change);
    // Changes only the finest operator (what CG solves with) and keeps the preconditioner built
    // for an earlier one: a lagged preconditioner, as long as the operator changes little.
    void update_fine_operator(const std::function<void(Operator &)> &change);
    // CG's stopping tolerance relative to |f - K g| for the next solves (inexact Newton).
    void set_relative_tolerance(double tolerance) { settings.relative_tolerance = tolerance; }

    // Solves K u = f where u takes the prescribed values of 'constraints' (inhomogeneous).
    // condensed_rhs is C^T f with zero constrained rows (distribute_local_to_global of the cell
    // right-hand sides alone). Returns u on owned DoFs with constrained entries zero: the caller
    // runs constraints.distribute(). Throws dealii::SolverControl::NoConvergence. Without a
    // warm start CG starts from zero and stops at relative_tolerance times |f - K g|.
    unsigned int solve(const dealii::PETScWrappers::MPI::Vector &condensed_rhs,
                       const dealii::AffineConstraints<double>   &constraints,
                       dealii::PETScWrappers::MPI::Vector         &solution,
                       const WarmStart                           *start = nullptr);

    // One V-cycle on vectors of the finest level (dst = P^-1 src).
    void precondition(VectorType &dst, const VectorType &src) const;

    const PMultigridStatistics &statistics() const { return stats; }
    // The degree-1 level (matrix, solver, fingerprint), to hand to another solver of this mesh.
    std::shared_ptr<DegreeOneLevel> degree_one_level() const;

  private:
    // fingerprint: the degree-1 DoFs' (empty in update(): the mesh has not changed).
    void build_smoother_and_coarse_solver(const std::vector<double> &fingerprint);
    // Levels 0 (the lower solver's finest) and 1 (fine_dofs); false if lower does not fit.
    bool build_on_lower(const dealii::DoFHandler<dim> &fine_dofs, const LevelConstraints &level_constraints,
                        const LevelSetup &level_setup, std::shared_ptr<const PMultigridSolver> lower);
    // Builds the long-edge space on the degree-2 level where it pays and fits; true if it does.
    bool choose_long_edge_space(double aspect_ratio, double memory);
    // The transfers between the levels (fast_solver/level_transfer.h).
    void build_transfer();
    // The V-cycle's objects over the current levels, smoother and coarse solve.
    void build_preconditioner();

    struct Levels;
    std::unique_ptr<Levels> levels;
    PMultigridSettings      settings;
    PMultigridStatistics    stats;
    MPI_Comm                communicator;
    std::vector<dealii::PETScWrappers::MPI::Vector> coarse_rigid_body_modes;
  };
} // namespace compliant::fast_solver
