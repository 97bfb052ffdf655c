// Total-Lagrangian finite-strain elasticity (plane strain and 3D): displacement-only, or mixed
// displacement-pressure (Q_p / discontinuous P_(p-1) pressure) against volumetric locking.
// Newton-Raphson (nonlinear/newton.h) with the consistent tangent and a backtracking line search;
// loads and imposed motions are scaled by a load factor that the path driver steps.
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

#include "constraints/extra_constraints.h"
#include "constraints/rigid_boundary.h"
#include "contact/contact_set.h"
#include "discretization/discretization.h"
#include "finite_strain/hyperelastic_law.h"
#include "nonlinear/arc_length.h"
#include "nonlinear/newton.h"

#include <functional>
#include <memory>
#include <stdexcept>

namespace compliant::fast_solver
{
  template <int dim, typename Operator>
  class PMultigridSolver;
  template <int dim, typename Number>
  class TangentOperator;
} // namespace compliant::fast_solver

namespace compliant
{
  class DirectFactorization; // linear_algebra/direct_factorization.h

  struct FiniteStrainSettings
  {
    std::string law = "neo-Hookean";
    double      mooney_rivlin_ratio = 0;
    std::string law_constants; // 'Finite strain/Law constants' (finite_strain/law_constants.h)
    bool        mixed = false;
    std::string follower_pressure; // 'boundary: expression' (reference coordinates x, y, z)
    unsigned    max_newton_iterations = 25;
    double      residual_tolerance = 1e-9; // relative to the internal force scale
    unsigned    line_search_steps  = 5;
    // 'Finite strain/Predictor' = secant: a load step forward starts from the secant through the
    // last two converged states (predict_by_secant); false: from the last converged state.
    bool        secant_predictor   = true;
    ContactSettings contact; // subsection Contact: rigid obstacles
    // Extra constraints (pins, mirror ties, edge supports): lines on the displacements of the
    // reference configuration (finite_strain_extra_constraints.cc).
    ExtraConstraints extra;
  };

  template <int dim>
  class FiniteStrainNewtonSystem; // finite_strain_newton.cc: this problem as Newton sees it
  template <int dim>
  class FiniteStrainContinuationSystem; // finite_strain_arc_length.cc: as arc-length sees it

  template <int dim>
  class FiniteStrainProblem : public Discretization<dim>
  {
  public:
    using Base = Discretization<dim>;
    using Base::parameters, Base::geometry, Base::communicator, Base::mesh_partition, Base::triangulation,
      Base::fe, Base::mapping, Base::quadrature, Base::face_quadrature, Base::dof_handler,
      Base::locally_owned_dofs, Base::locally_relevant_dofs, Base::hanging_node_constraints, Base::materials,
      Base::boundary_conditions, Base::thickness, Base::mixed, Base::plane_stress;

    FiniteStrainProblem(const CaseParameters &parameters, const FiniteStrainSettings &settings,
                        const MeshedGeometry &geometry, MPI_Comm communicator,
                        const MeshPartitionChoice &partition = {});
    ~FiniteStrainProblem();

    void setup();

    // Newton from the current state to the given load factor. On success the state is updated;
    // on failure (no convergence, det F <= 0, linear solver) the state is restored and a
    // StepFailure says why. A step forward from the end of the last one starts from the secant
    // through the last two converged states (falling back to the current state if Newton fails
    // from there).
    NewtonReport solve_to(double load_factor);

    // Arc-length continuation from the current state to load factor 1 (loads only, no prescribed
    // motion: std::invalid_argument otherwise). on_step sees each converged step with the problem
    // at its state; the state stays at the last one.
    // Throws std::invalid_argument (collectively) if a boundary condition prescribes motion.
    void            require_load_driven() const;
    ArcLengthResult follow_arc_length(const ArcLengthSettings &settings,
                                      const std::function<void(const ArcLengthStep &)> &on_step,
                                      const std::function<void(double, const std::string &, double)> &on_cutback);

    // Cauchy stress (and its out-of-plane component in plane strain) from a displacement gradient.
    dealii::SymmetricTensor<2, dim> cauchy_stress(const dealii::Tensor<2, dim> &grad_u,
                                                  const Material &material, double pressure,
                                                  double &sigma_zz) const;
    double von_mises(const dealii::SymmetricTensor<2, dim> &stress, double sigma_zz) const;
    double energy_density(const dealii::Tensor<2, dim> &grad_u, const Material &material,
                          double pressure = 0) const; // W(F): the pressure is not needed

    // Returns to an earlier converged state (a step the analysis rejects after the fact).
    void restore(const dealii::PETScWrappers::MPI::Vector &state, double state_load_factor)
    {
      solution                = state;
      load_factor             = state_load_factor;
      secant.load_factor_then = -1; // the secant predictor's last step no longer ends here
    }
    // Contact: the converged state's active sets (obstacles and pairs) are saved; with friction
    // the next load step also starts with the held nodes sticking where this state has them.
    void start_contact_step();
    // Contact: back to the state saved by start_contact_step (after a failed Newton or a
    // rejected step).
    void restore_contact_state();
    // The contact active set at state u (ghosted) and load factor lambda, from its contact forces
    // (full: the unconstrained residual there, assembled here); `release` lets pulling nodes go.
    // Shared by Newton and the arc-length corrector. Collective.
    typename ContactSet<dim>::Update update_contact_set(const dealii::PETScWrappers::MPI::Vector &u, double lambda,
                                                        bool release, dealii::PETScWrappers::MPI::Vector &full);
    // The residual, relative to the force scale, below which a state's contact forces decide
    // which nodes are freed (quadratic convergence: the next state is then at equilibrium to
    // about its square).
    static constexpr double contact_release_residual = 1e-2;
    // Contact between boundaries (Contact/Pairs): a held node's constraint reaches the master
    // surface's nodes it faces now, so the tangent's pattern is rebuilt whenever the constraints
    // refer to a coupling it lacks. Collective.
    // (assemble does it before it assembles the tangent.)
    void cover_contact_couplings(const dealii::AffineConstraints<double> &constraints) const;

    // Negative eigenvalues of the condensed tangent stiffness at the current state (0: stable
    // equilibrium under the applied loads; a limit point or bifurcation has been passed
    // otherwise). Mixed formulations: the pressure block's own negative eigenvalues are removed
    // by Sylvester's law of inertia. Needs a symmetric tangent (no follower pressure).
    unsigned int unstable_modes() const;

    // The tangent at the current state, condensed with the homogeneous constraints returned in
    // `homogeneous` (a reference to the problem's matrix, overwritten by the next assembly).
    const dealii::PETScWrappers::MPI::SparseMatrix &
    assemble_tangent(dealii::AffineConstraints<double> &homogeneous) const;

    // Check of the consistent tangent: |K v - (R(u + h v) - R(u - h v)) / 2h| / |K v| at the
    // state u (unconstrained; meant for problems without Dirichlet conditions).
    double tangent_consistency(const dealii::PETScWrappers::MPI::Vector &u,
                               const dealii::PETScWrappers::MPI::Vector &v, double lambda,
                               double h) const;

    // K v at the state u (Dirichlet DoFs held: identity rows), from the assembled tangent or the
    // matrix-free operator of the fast solver; the two must agree to round-off.
    dealii::PETScWrappers::MPI::Vector tangent_action(const dealii::PETScWrappers::MPI::Vector &u,
                                                      const dealii::PETScWrappers::MPI::Vector &v,
                                                      double lambda, bool matrix_free) const;

    // The duals of goal-oriented refinement at the current (converged) state (ladder/
    // adaptive_refinement.h). The solver of K_T^T z = j: the tangent assembled and factored once
    // (MUMPS, LU; the transposed solve reuses the factors), `homogeneous` its constraints held at
    // zero; rows they hold are zeroed in j and z comes ghosted. The tangent is unsymmetric where a
    // follower pressure or a 3D rigid moment acts: the adjoint needs its transpose.
    // `homogeneous` must outlive the returned function.
    std::function<dealii::PETScWrappers::MPI::Vector(dealii::PETScWrappers::MPI::Vector)>
    tangent_dual_solver(dealii::AffineConstraints<double> &homogeneous) const;
    // K_T psi by central differences of the internal forces, condensed by `homogeneous`: a
    // reaction's j, whose psi lives on a supported boundary (the assembled tangent has no columns
    // there).
    dealii::PETScWrappers::MPI::Vector
    tangent_times(const dealii::PETScWrappers::MPI::Vector &psi, const dealii::AffineConstraints<double> &homogeneous) const;

    // Whether Newton steps use the matrix-free p-multigrid (Linear solver/Method auto or
    // matrix-free, degree >= 2, displacement-only, no follower pressure), and why not.
    bool        matrix_free_tangent() const;
    static constexpr unsigned int auto_matrix_free_dofs = 1000; // 3D, Method = auto
    std::string linear_solver_description() const;

    // f_int(u) - f_ext(u) without constraints: the support reactions.
    dealii::PETScWrappers::MPI::Vector reaction_forces() const;
    std::map<std::string, double>      expression_variables() const;

    const FiniteStrainSettings                  &settings;
    std::map<int, HyperelasticLaw>               laws;
    // Asked (collectively) before every Newton iteration; true stops the step with
    // RunInterrupted. Empty: never.
    std::function<bool()>                        stop_requested;
    double                                       load_factor = 0; // of the current state
    static constexpr bool                        geometrically_nonlinear = true;

    dealii::PETScWrappers::MPI::Vector solution; // ghosted, converged state
    // Boundary conditions/Rigid; linearised at the state of the latest make_constraints.
    mutable std::vector<RigidBoundary<dim>> rigid_boundaries;
    // Contact with rigid obstacles (Contact/Obstacles); null without obstacles. Its active set is
    // chosen inside Newton (FiniteStrainNewtonSystem::linearize) and held by make_constraints.
    std::unique_ptr<ContactSet<dim>>   contact;
    mutable std::vector<std::pair<dealii::types::global_dof_index, dealii::types::global_dof_index>> contact_couplings;
    unsigned int                       total_linear_solves = 0;
    double                             tangent_assembly_seconds = 0, linear_solve_seconds = 0;
    double                             contact_seconds = 0; // active-set updates (a residual each)
    // Of linear_solve_seconds: the matrix-free tangent's state on the finest level every Newton
    // step, and at each rebuild every level's, diagonals, eigenvalue estimates and the degree-1
    // factorization.
    double                             preconditioner_setup_seconds = 0;
    // CG iterations over all Newton steps solved iteratively; set once CG failed (MUMPS after).
    unsigned int                       total_linear_iterations = 0;
    // Of total_linear_solves: how often the p-multigrid preconditioner was rebuilt (the others
    // reused one built at an earlier state).
    unsigned int                       preconditioner_builds = 0;
    bool                               iterative_failed        = false;
    std::string                        iterative_failure; // why the iterative solver was left

    // Throws std::invalid_argument naming the rigid motions the supports, ties and rigid
    // boundaries leave free in the reference configuration (constraints/rigid_motion_check.h).
    // Not for contact, which may hold the part once it touches. Collective.
    void require_rigid_motion_held(const std::string &what) const;

    // The norm below which a Newton correction is round-off of the state itself. Rigid boundaries
    // place their nodes at x_c + R (X - pivot) and take u = x - X, a few eps of the largest
    // coordinate per DoF: measured on a steel box 5 x 1 x 1 in SI units (m, Pa) under 0.1 N
    // (displacements 1e-9 of its size), the residual stalled at 3e-4 of the force scale, and the
    // corrections at 1e-16 (case.rigid_boundary_stiff_units: a 10 m bar under 1 N). 0 without rigid boundaries. Collective on its first call.
    double correction_round_off() const;

    // Norms of the mixed formulation's vectors in one unit: its pressure rows are volumes and its
    // pressures stresses, beside forces and lengths. A residual's pressure rows count times mu / h,
    // an unknown's pressures times h / mu (mu the largest shear modulus, h the mean cell size),
    // so that scaling E leaves every test unchanged. Measured before (E and loads x 1e-6): the
    // pressure rows' round-off stood above the force tolerance and the arc length ended past its
    // load factor (1.049); x 1e6, the pressures ruled the arc length (54 steps instead of 88).
    // Plain l2 norms and dot products without the mixed formulation. Collective.
    double residual_norm_of(const dealii::PETScWrappers::MPI::Vector &residual) const;
    double unknown_dot(const dealii::PETScWrappers::MPI::Vector &a, const dealii::PETScWrappers::MPI::Vector &b) const;

  private:
    mutable double largest_coordinate = -1; // of the mesh's vertices, over all ranks
    // 1 on displacement DoFs, mu / h on pressure DoFs (owned entries); built on first use.
    mutable dealii::PETScWrappers::MPI::Vector pressure_weight, inverse_pressure_weight;
    const dealii::PETScWrappers::MPI::Vector  &pressure_weights() const;
    friend class FiniteStrainNewtonSystem<dim>;
    friend class FiniteStrainContinuationSystem<dim>;
    // The law of a body's material (for output): the one made at setup.
    HyperelasticLaw law_of(const Material &material) const;
    // The law's response at one point: plane stress (2D) or plane strain/3D; the tangent only
    // `with_tangent` (HyperelasticLaw::response).
    StressResponse<dim> material_response(const HyperelasticLaw &law,
                                          const dealii::SymmetricTensor<2, dim> &E,
                                          double pressure, bool with_tangent = true) const;
    // Dirichlet values at load factor `lambda` minus the current displacement (first Newton
    // iteration), or homogeneous (later iterations).
    // Rigid boundaries are linearised at u; for_sparsity: their lines name every DoF that may
    // become a master (the matrix's pattern).
    dealii::AffineConstraints<double> make_constraints(double lambda, bool homogeneous,
                                                       const dealii::PETScWrappers::MPI::Vector &u,
                                                       bool for_sparsity = false) const;
    // Contact/Obstacles against the mesh (std::invalid_argument naming the entry).
    void set_up_contact();
    // Extra constraints: their lines, made once against the supports (std::invalid_argument
    // naming the entry). With them every rank keeps every constraint line: a pin ties DoFs of
    // bodies any ranks own, and its supported pin must be known where its eyes are.
    void set_up_extra_constraints();
    // Adds the extra constraints' lines (homogeneous: the state satisfies them) to constraints
    // that hold every line (the supports already in).
    void add_extra_lines(dealii::AffineConstraints<double> &constraints) const;
    // The displacement u with the DoFs the extra lines name ghosted as well (the support values
    // their chains take); u itself without extra constraints.
    void state_for_constraints(const dealii::PETScWrappers::MPI::Vector &u,
                               dealii::PETScWrappers::MPI::Vector       &state) const;
    std::vector<dealii::AffineConstraints<double>::ConstraintLine> extra_lines;
    dealii::IndexSet                                               extra_dofs; // every DoF they name
    // u + alpha du, with every rigid boundary put on its exact rigid motion.
    void add_correction(dealii::PETScWrappers::MPI::Vector &u, double alpha,
                        const dealii::PETScWrappers::MPI::Vector &du) const;
    // K v at state u by central differences of the residual with step h, assembled under
    // `constraints` (null: none).
    dealii::PETScWrappers::MPI::Vector central_difference(const dealii::PETScWrappers::MPI::Vector &u,
                                                          const dealii::PETScWrappers::MPI::Vector &v, double lambda,
                                                          double h, const dealii::AffineConstraints<double> *constraints) const;
    // Assembles the residual lambda f_ext - f_int (and the tangent if asked) at state u.
    // full_residual, if given, also gets it without the Dirichlet conditions (hanging nodes
    // condensed): the internal force scale of the convergence test, from the same pass.
    // Throws StepFailure when an element inverts.
    void assemble(const dealii::PETScWrappers::MPI::Vector &u, double lambda,
                  const dealii::AffineConstraints<double> *constraints, bool with_matrix,
                  dealii::PETScWrappers::MPI::Vector &residual,
                  dealii::PETScWrappers::MPI::Vector *full_residual = nullptr) const;
    double residual_norm(const dealii::PETScWrappers::MPI::Vector &u, double lambda,
                         const dealii::AffineConstraints<double> &homogeneous) const;

    // One Newton correction by CG with the p-multigrid on the matrix-free tangent at state u
    // (ghosted); rhs is C^T r. Returns the CG iterations; throws std::runtime_error on failure.
    unsigned int solve_matrix_free(const dealii::PETScWrappers::MPI::Vector &u,
                                   const dealii::PETScWrappers::MPI::Vector &rhs,
                                   const dealii::AffineConstraints<double>  &constraints,
                                   dealii::PETScWrappers::MPI::Vector       &du);
    // du = K^-1 rhs on the assembled tangent by MUMPS, kept from one Newton iteration to the
    // next: the analysis is redone only when the tangent's sparsity changes, and a symmetric
    // tangent is factored LDL^T (finite_strain_linear_solver.cc).
    void solve_direct(dealii::PETScWrappers::MPI::Vector &du, const dealii::PETScWrappers::MPI::Vector &rhs);
    bool symmetric_tangent() const;
    std::shared_ptr<DirectFactorization> newton_factorization;
    // The state before the last step solve_to took, for the secant predictor: valid while the
    // current state is that step's end (load_factor_then == load_factor).
    struct SecantHistory
    {
      dealii::PETScWrappers::MPI::Vector start;
      double                             load_factor_start = 0, load_factor_then = -1;
    } secant;
    // The predictor's start for a step to `target` in u, or false (no history, a step back,
    // contact: its active set belongs to the converged state).
    bool predict_by_secant(double target, dealii::PETScWrappers::MPI::Vector &u) const;
    void add_level_constraints(const dealii::DoFHandler<dim>     &dofs,
                               dealii::AffineConstraints<double> &constraints) const;

    using TangentMultigrid =
      fast_solver::PMultigridSolver<dim, fast_solver::TangentOperator<dim, double>>;
    std::unique_ptr<TangentMultigrid>               tangent_multigrid; // built at the first step
    // Inexact Newton: the residual reduction the next matrix-free correction needs (set by Newton),
    // at most newton_forcing_max. Measured on cases/benchmarks/flexure_finite_strain.prm at 20.7k
    // DoFs (6 load steps): 0.1 left the first correction after each step's predictor so poor
    // that Newton took 45 iterations and the step control 7 steps, against 30 and 6 solved to
    // 1e-8; 1e-2 took 32 Newton iterations, 288 CG iterations against 646, and the same answer.
    static constexpr double newton_forcing_max = 1e-2;
    double                  linear_forcing     = 1e-8;
    // The lagged preconditioner: CG iterations per decade of residual reduction right after the
    // last rebuild, and whether the latest solve was so much slower that the next rebuilds it.
    // Rebuilt when a lagged solve needs more than this factor (plus one) of those iterations:
    // 5 builds in 32 Newton steps on the benchmark above, 288 CG iterations; never rebuilt, 395.
    double                  preconditioner_rate                = 0;
    bool                    preconditioner_stale               = true;
    static constexpr double lagged_preconditioner_slowdown     = 1.5;
    mutable dealii::PETScWrappers::MPI::SparseMatrix tangent;
    std::map<int, std::vector<std::string>>          follower_pressures; // per boundary id
    std::map<int, dealii::Tensor<1, dim>>            dead_tractions;
    double                                           force_scale = 0;
  };
} // namespace compliant
