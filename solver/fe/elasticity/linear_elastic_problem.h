// Linear elasticity on a METIS-partitioned (shared or fully distributed) mesh with PETSc matrices:
// 2D plane stress / plane strain and 3D, quadrilateral/hexahedral or simplex meshes, degree 1-3.
#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "constraints/rigid_boundary.h"
#include "discretization/discretization.h"
#include "linear_algebra/solver_method.h"

#include <memory>

namespace compliant::fast_solver
{
  struct DegreeOneLevel; // fast_solver/coarse_level_solver.h
  template <int dim, typename Number>
  class ElasticityOperator;
  template <int dim, typename Operator>
  class PMultigridSolver;
} // namespace compliant::fast_solver

namespace compliant
{
  class DirectFactorization; // linear_algebra/direct_factorization.h

  struct SolverStatistics
  {
    unsigned int iterations = 0;
    double       setup_seconds = 0, assembly_seconds = 0, solve_seconds = 0;
    // Matrix-free p-multigrid: set-up of the levels (inside solve_seconds), DoFs per level.
    double                    preconditioner_setup_seconds = 0;
    unsigned int              coarse_iterations = 0; // inner CG on degree 1, summed
    double                    initial_residual  = 0; // |f - K u0| of the matrix-free solve, u0 its start
    bool                      degree_one_reused = false; // another model's degree-1 level served
    bool                      lower_multigrid_reused = false; // another model's V-cycle below degree p
    std::vector<std::size_t>  level_dofs;
    std::string               multigrid_note; // smoother and coarse solve, and why
  };

  template <int dim>
  class LinearElasticProblem : public Discretization<dim>
  {
  public:
    using Base = Discretization<dim>;
    using Base::parameters, Base::geometry, Base::communicator, Base::mesh_partition, Base::triangulation,
      Base::fe, Base::mapping, Base::quadrature, Base::face_quadrature, Base::dof_handler,
      Base::locally_owned_dofs, Base::locally_relevant_dofs, Base::hanging_node_constraints, Base::materials,
      Base::boundary_conditions, Base::thickness, Base::mixed, Base::plane_stress;

    // The mesh is shared unless the analysis chose to distribute it (mesh/mesh_partition.h).
    LinearElasticProblem(const CaseParameters &parameters, const MeshedGeometry &geometry,
                         MPI_Comm communicator, const MeshPartitionChoice &partition = {});

    // Builds mesh, DoFs and constraints and decides the linear solver (solver_method); every
    // case-file name is checked here, before any work or output (throws std::invalid_argument).
    void setup();
    // The part of setup() that needs no supports: mesh, elements, materials, conditions, DoFs,
    // vectors, hanging-node constraints only (a free-free modal analysis starts from here).
    void setup_discretization();
    // The right-hand side, and the stiffness matrix unless the solver is matrix-free.
    void assemble();
    void solve();
    // Adds hanging-node and support constraints (clamped, displacement, rotation; the first
    // condition wins on shared edges) for any DoFHandler of this mesh; homogeneous: values zero.
    void add_support_constraints(const dealii::DoFHandler<dim>     &dofs,
                                 dealii::AffineConstraints<double> &constraints,
                                 bool                               homogeneous) const;
    // The dual (adjoint) problem of a goal functional J(v) = j . v: K z = j with every support
    // homogeneous, by the same operator and solver as the primal (K is symmetric), so it costs one
    // primal solve. j must be assembled through homogeneous_constraints(). Returns z, ghosted.
    dealii::PETScWrappers::MPI::Vector solve_dual(const dealii::PETScWrappers::MPI::Vector &j);
    // The constraints with every prescribed value zero: the space of the dual.
    dealii::AffineConstraints<double> homogeneous_constraints() const;
    // Called by whoever installs constraints beyond the supports (pins, ties): the matrix-free
    // levels could not represent them, so the solve falls back to an assembled matrix.
    void require_assembled_matrix(const std::string &reason);

    // Stress at a point from the displacement gradient: sigma = lambda tr(eps) I + 2 mu eps
    // (plane stress uses the reduced lambda). Also returns sigma_zz for von Mises in 2D.
    dealii::SymmetricTensor<2, dim> stress(const dealii::SymmetricTensor<2, dim> &strain,
                                           const Material &material, double &sigma_zz) const;
    double von_mises(const dealii::SymmetricTensor<2, dim> &stress, double sigma_zz) const;
    // The same from a displacement gradient (the interface the quantities and fields use; the
    // pressure argument exists for mixed formulations and is ignored here).
    dealii::SymmetricTensor<2, dim> cauchy_stress(const dealii::Tensor<2, dim> &grad_u,
                                                  const Material &material, double pressure,
                                                  double &sigma_zz) const;
    // Strain energy density; the pressure enters in the mixed formulation (0.5 sigma : eps).
    double energy_density(const dealii::Tensor<2, dim> &grad_u, const Material &material,
                          double pressure = 0) const;
    // f_int(u) - f_ext without constraints: nonzero only where supports act, the reactions.
    dealii::PETScWrappers::MPI::Vector reaction_forces() const;

    // Everything the quantities and the output read, beyond the discretization: the support
    // constraints (hanging nodes included).
    dealii::AffineConstraints<double>           constraints;
    // install_constraints (elasticity/global_constraints.h) replaced them by the whole set on
    // every rank, extra constraints (pins, ties, edge supports) included.
    bool constraints_gathered = false;
    // Boundary conditions/Rigid, linearised about the reference configuration.
    std::vector<RigidBoundary<dim>>             rigid_boundaries;
    // Discretization/Formulation = mixed (the base's `mixed`): u-p with a discontinuous pressure,
    // sigma = 2 mu eps - p I, div u + p / lambda = 0 weakly (the pressure is the last component).
    // The quantities' interface shared with the finite-strain problem.
    static constexpr bool   geometrically_nonlinear = false;
    static constexpr double load_factor             = 1;

    // Set by an analysis before setup() when it only needs K u = f solved (linear static): then
    // 'auto' and 'matrix-free' may skip the assembled matrix.
    bool matrix_free_allowed = false;
    // Set before solve() to start the matrix-free solve from this guess (owned DoFs) and stop it
    // once the residual has dropped by warm_start_reduction from the guess's: the error
    // estimates' enriched model starts from the degree-p solution. Ignored by MUMPS and GAMG.
    dealii::PETScWrappers::MPI::Vector warm_start;
    double                             warm_start_reduction = 1e-3;
    // With Quantities/Error estimates, the matrix-free solve's degree-1 level (matrix and AMG) is
    // kept here; the enriched model of the same mesh, given it before its solve in
    // reused_degree_one_level, uses it instead of building its own.
    std::shared_ptr<fast_solver::DegreeOneLevel> degree_one_level, reused_degree_one_level;
    // Likewise the matrix-free model's whole solver: the enriched model's multigrid then builds
    // its degree-(p+1) level only and takes this one's V-cycle as its coarse solve.
    std::shared_ptr<const fast_solver::PMultigridSolver<dim, fast_solver::ElasticityOperator<dim, double>>>
      multigrid, reused_lower_multigrid;
    // MUMPS: the factor of the last solve, kept until the next assembly, so that a dual of the
    // same matrix (goal-oriented refinement) is a back-substitution.
    std::shared_ptr<DirectFactorization> factorization;
    // Set before solve() on the error estimates' once-refined model (simplices at their highest
    // degree): the same case's model on the unrefined mesh, solved by MUMPS. The solve is then CG
    // preconditioned by smoothing here and that model's factor below (linear_algebra/
    // two_level_solver.h), from its solution carried here, to warm_start_reduction; as before
    // where the meshes are not twins (solver_note says why) or CG does not converge.
    const LinearElasticProblem<dim> *coarse_twin = nullptr;
    // Set before solve() by whoever solves duals of this matrix (goal-oriented refinement): the
    // matrix-free p-multigrid is then kept and serves them, set-up and all.
    bool keep_solver_for_duals = false;
    std::shared_ptr<fast_solver::PMultigridSolver<dim, fast_solver::ElasticityOperator<dim, double>>> kept_solver;
    // The solver actually used (Linear solver/Method with 'auto' resolved) and why, for the log.
    SolverMethod solver_method = SolverMethod::automatic; // the one chosen
    std::string  solver_note;

    dealii::PETScWrappers::MPI::SparseMatrix system_matrix;
    dealii::PETScWrappers::MPI::Vector       system_rhs;
    // External forces without constraints applied: the reactions are f_int(u) - f_ext.
    dealii::PETScWrappers::MPI::Vector       external_forces; // C^T f (hanging nodes condensed)
    dealii::PETScWrappers::MPI::Vector       solution; // ghosted (locally relevant)
    SolverStatistics                         statistics;

  private:
    void make_constraints();
    void choose_solver_method();
    void allocate_matrix();
    // Solves with the matrix-free p-multigrid; false if it did not converge and 'auto' allows
    // falling back (solver_note says so).
    bool solve_matrix_free(dealii::PETScWrappers::MPI::Vector &x);
    // MUMPS LDL^T of system_matrix, factored at the first solve after an assembly; returns 1.
    unsigned int solve_direct(dealii::PETScWrappers::MPI::Vector &x);
    // The two-level solve from coarse_twin; false (x zero) where it does not apply or fails.
    bool solve_from_coarse_twin(dealii::PETScWrappers::MPI::Vector &x);
    // Traction from Loads/Traction and Loads/Total force, per boundary id.
    std::map<int, dealii::Tensor<1, dim>> boundary_tractions() const;
    double boundary_measure(int boundary_id) const;
  };
} // namespace compliant
