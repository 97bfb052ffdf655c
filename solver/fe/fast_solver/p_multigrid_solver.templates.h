// Implementation of PMultigridSolver, included by one translation unit per operator type.
#pragma once

#include "fast_solver/p_multigrid_solver.h"

#include <deal.II/base/mg_level_object.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/lac/diagonal_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/precondition.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/multigrid/mg_coarse.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/mg_smoother.h>
#include <deal.II/multigrid/multigrid.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "discretization/dof_fingerprint.h"
#include "fast_solver/coarse_level_solver.h"
#include "fast_solver/level_transfer.h"
#include "fast_solver/long_edge_coarse_solver.h"
#include "mesh/cell_aspect_ratio.h"
#include "mesh/memory_estimate.h"
#include "linear_algebra/rigid_body_modes.h"

namespace compliant::fast_solver
{
  using namespace dealii;

  template <int dim, typename Operator_>
  struct PMultigridSolver<dim, Operator_>::Levels
  {
    using VectorType     = LinearAlgebra::distributed::Vector<double>;
    using Operator       = Operator_;
    using SmootherType   = PreconditionChebyshev<Operator, VectorType, DiagonalMatrix<VectorType>>;
    using TransferType   = LevelTransfer<dim>;

    // A lower solver's V-cycle as the coarse solve of the level above it.
    struct LowerCycle : public MGCoarseGridBase<VectorType>
    {
      std::shared_ptr<const PMultigridSolver> lower;
      void operator()(const unsigned int, VectorType &dst, const VectorType &src) const override
      {
        lower->precondition(dst, src);
      }
    };

    // Level l holds degree l + 1; the finest is the problem's own DoFHandler. On a lower solver:
    // two levels, level 0 its finest (degree p), level 1 this solver's (degree p + 1).
    std::vector<std::unique_ptr<FESystem<dim>>>    coarse_elements;
    std::vector<std::unique_ptr<DoFHandler<dim>>>  coarse_dofs;
    MGLevelObject<const DoFHandler<dim> *>         dofs;
    MGLevelObject<AffineConstraints<double>>       constraints;
    MGLevelObject<std::shared_ptr<Operator>>       operators;
    std::unique_ptr<TransferType>                  transfer;
    std::shared_ptr<DegreeOneLevel>                coarse;
    LowerCycle                                     lower_cycle; // its `lower` set: the coarse solve
    const Mapping<dim>                            *mapping = nullptr;
    MGSmootherPrecondition<Operator, SmootherType, VectorType> smoother;
    // On long cells: the long-edge space below the degree-2 level (level 1), which is then the
    // lowest level the V-cycle visits; level 0 is laid out (its vectors) but not used. Declared
    // after the smoother it uses and before the V-cycle that holds it: destroyed in between.
    std::shared_ptr<const LongEdgeSpace>           long_edges;
    std::unique_ptr<LongEdgeCoarseSolver<dim>>     long_edge_solve;
    std::unique_ptr<mg::Matrix<VectorType>>        mg_matrix;
    std::unique_ptr<Multigrid<VectorType>>         multigrid;
    std::unique_ptr<PreconditionMG<dim, VectorType, TransferType>> preconditioner;

    const MGCoarseGridBase<VectorType> &coarse_solve() const
    {
      if (lower_cycle.lower)
        return lower_cycle;
      if (long_edge_solve)
        return *long_edge_solve;
      return *coarse->solver;
    }
    // Inner iterations of the degree-1 solver, this solver's or the lower one's.
    unsigned int coarse_inner_iterations() const
    {
      return lower_cycle.lower ? lower_cycle.lower->levels->coarse_inner_iterations() :
             long_edge_solve   ? long_edge_solve->solves() :
                                 coarse->solver->inner_iterations();
    }
  };

  namespace
  {
    // Whether two triangulations are twins with the same cells on this rank as on every other:
    // the sums over the locally owned cells of (index + 1) times each coordinate of the centre.
    template <int dim>
    bool same_owned_cells(const Triangulation<dim> &a, const Triangulation<dim> &b, MPI_Comm communicator)
    {
      const auto sums = [](const Triangulation<dim> &mesh) {
        std::vector<double> s(dim + 1, 0.);
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              for (unsigned int d = 0; d < dim; ++d)
                s[d] += (cell->active_cell_index() + 1.) * cell->center()[d];
              s[dim] += 1;
            }
        return s;
      };
      const bool same = a.n_active_cells() == b.n_active_cells() && sums(a) == sums(b);
      return Utilities::MPI::min(same ? 1 : 0, communicator) == 1;
    }
  } // namespace


  template <int dim, typename Operator>
  PMultigridSolver<dim, Operator>::PMultigridSolver(const Mapping<dim>       &mapping,
                                                    const DoFHandler<dim>    &fine_dofs,
                                                    const LevelConstraints   &level_constraints,
                                                    const LevelSetup         &level_setup,
                                                    const PMultigridSettings &settings_in,
                                                    MPI_Comm                  communicator_in,
                                                    std::shared_ptr<const PMultigridSolver> lower)
    : levels(std::make_unique<Levels>())
    , settings(settings_in)
    , communicator(communicator_in)
  {
    Timer timer;
    levels->mapping = &mapping;
    if (lower && build_on_lower(fine_dofs, level_constraints, level_setup, lower))
      {
        build_smoother_and_coarse_solver({});
        stats.setup_seconds = timer.wall_time();
        return;
      }
    const unsigned int fine_degree = fine_dofs.get_fe().degree;
    const unsigned int top         = fine_degree - 1;
    auto              &L           = *levels;
    L.dofs.resize(0, top);
    L.constraints.resize(0, top);
    L.operators.resize(0, top);
    L.mapping = &mapping;

    // A reused degree-1 level kept with its DoFs (a degree-1 model on a twin mesh) is level 0 as it is.
    const auto &reused     = settings.reused_degree_one_level;
    const auto *kept_dofs  = reused && top == 1 ? reused->template dofs<dim>() : nullptr;
    // Twin meshes owned alike, and the kept DoFs still numbered as when the level's solver was built.
    const bool take_kept =
      kept_dofs &&
      Utilities::MPI::min(reused->owned == kept_dofs->locally_owned_dofs() &&
                              !reused->fingerprint.empty() && reused->fingerprint.back() == kept_dofs->n_dofs() ?
                            1 :
                            0,
                          communicator) == 1 &&
      same_owned_cells(kept_dofs->get_triangulation(), fine_dofs.get_triangulation(), communicator);
    for (unsigned int level = 0; level <= top; ++level)
      {
        if (level == top)
          L.dofs[level] = &fine_dofs;
        else if (take_kept)
          {
            L.dofs[level] = kept_dofs;
            L.constraints[level].copy_from(reused->constraints);
            stats.level_dofs.push_back(kept_dofs->n_dofs());
            continue;
          }
        else
          {
            L.coarse_elements.push_back(std::make_unique<FESystem<dim>>(FE_Q<dim>(level + 1), dim));
            L.coarse_dofs.push_back(std::make_unique<DoFHandler<dim>>(fine_dofs.get_triangulation()));
            L.coarse_dofs.back()->distribute_dofs(*L.coarse_elements.back());
            L.dofs[level] = L.coarse_dofs.back().get();
          }
        level_constraints(*L.dofs[level], L.constraints[level]);
        L.constraints[level].close();
        stats.level_dofs.push_back(L.dofs[level]->n_dofs());
      }

    const auto fingerprint = take_kept ? std::vector<double>() : degree_one_fingerprint(*L.dofs[0], communicator);
    stats.coarse_reused    = take_kept || (reused && degree_one_level_fits(*reused, *L.dofs[0], fingerprint, communicator));
    stats.largest_aspect_ratio = largest_cell_aspect_ratio(fine_dofs.get_triangulation(), communicator);
    const double a             = stats.largest_aspect_ratio;
    // The smallest over the ranks: each rank reads its own node at its own moment, and the
    // choices below must be the same on every rank.
    const double memory        = Utilities::MPI::min(available_memory(), communicator);
    const bool   long_edges    = choose_long_edge_space(a, memory);
    for (unsigned int level = 0; level <= top; ++level)
      {
        L.operators[level] = std::make_shared<typename Levels::Operator>();
        // A reused degree-1 level is solved without this level's operator, and the long-edge space
        // replaces it: its vectors' layout only.
        if (level == 0 && (stats.coarse_reused || long_edges) && top > 0)
          L.operators[level]->reinit_layout(mapping, *L.dofs[level], L.constraints[level]);
        else
          level_setup(*L.operators[level], mapping, *L.dofs[level], L.constraints[level]);
      }
    build_transfer();

    // A 3D factor takes about 14 kB per degree-1 DoF over all ranks (measured at 63k-203k DoFs):
    // MUMPS only where that leaves half the available memory to the rest.
    const double n_coarse      = L.dofs[0]->n_dofs();
    const bool   factor_fits   = dim < 3 || memory <= 0 || 14e3 * n_coarse <= 0.5 * memory;
    stats.coarse_direct        = settings.coarse == PMultigridSettings::Coarse::direct ||
                          (settings.coarse == PMultigridSettings::Coarse::automatic && a > 3 && factor_fits &&
                           n_coarse <= (dim == 3 ? settings.direct_coarse_limit_3d : settings.direct_coarse_limit));
    if (stats.coarse_reused)
      L.coarse = reused, stats.coarse_direct = reused->direct;
    else if (long_edges)
      stats.coarse_direct = true;
    else
      coarse_rigid_body_modes = rigid_body_modes(mapping, *L.dofs[0], communicator);
    // Without the long-edge space, the diagonal has to damp the long cells' smooth modes: a wider
    // range with a higher polynomial, both from the aspect ratio a. With it, the range of cubes.
    const bool reduced     = long_edges && L.operators[1]->has_reduced_quadrature();
    stats.smoothing_range  = settings.smoothing_range > 0 ? settings.smoothing_range :
                             reduced                      ? settings.long_edge_reduced_smoothing_range :
                             long_edges                   ? settings.long_edge_smoothing_range :
                                                            std::clamp(3 * a * a, 20.0, 400.0);
    stats.smoothing_degree = settings.smoothing_degree > 0 ? settings.smoothing_degree :
                             reduced    ? settings.long_edge_reduced_smoothing_degree :
                             long_edges ? settings.long_edge_smoothing_degree :
                                          std::clamp<unsigned int>(std::lround(std::sqrt(stats.smoothing_range)) - 1, 4, 16);
    build_smoother_and_coarse_solver(fingerprint);
    stats.setup_seconds = timer.wall_time();
  }


  template <int dim, typename Operator>
  bool PMultigridSolver<dim, Operator>::choose_long_edge_space(const double aspect_ratio, const double memory)
  {
    auto &L = *levels;
    // Asked for GAMG: no factor. Asked for a factor (direct): the long-edge space's is one.
    if (!settings.long_edge_space || settings.coarse == PMultigridSettings::Coarse::amg ||
        L.dofs.max_level() < 1 || aspect_ratio <= settings.long_edge_aspect_ratio || stats.coarse_reused)
      return false;
    // Hanging nodes and ties: the space's blend does not follow them.
    if (constraints_have_entries(L.constraints[1], communicator))
      return false;
    // Where long cells remain in thick parts, the smoother has to be as wide as for the degree-1
    // level anyway, and that level serves as well for less (graded blade hinge, m = 2 and 3).
    const LongCells long_cells =
      find_long_cells(L.dofs[1]->get_triangulation(), settings.long_edge_aspect_ratio, settings.long_edge_slenderness);
    if (long_cells.thick_long_cells)
      {
        stats.thick_part_aspect_ratio = long_cells.largest_linear_aspect_ratio;
        return false;
      }
    auto space = std::make_shared<LongEdgeSpace>();
    build_long_edge_space(*L.dofs[1], L.constraints[1], long_cells, *space);
    const double n    = space->n_coarse;
    const bool   fits = dim < 3 || memory <= 0 || settings.long_edge_factor_bytes_per_dof * n <= 0.5 * memory;
    // The aspect ratio above is the longest edge over the shortest of any cell; a skewed cell can
    // pass it without being long in any direction, and then the space would be degree 1.
    if (space->n_free_nodes == 0 || !fits || n > (dim == 3 ? settings.direct_coarse_limit_3d : settings.direct_coarse_limit))
      return false;
    stats.long_edge_dofs = space->n_coarse;
    L.long_edges         = std::move(space);
    return true;
  }

  template <int dim, typename Operator>
  bool PMultigridSolver<dim, Operator>::build_on_lower(const DoFHandler<dim>                  &fine_dofs,
                                                       const LevelConstraints                 &level_constraints,
                                                       const LevelSetup                       &level_setup,
                                                       std::shared_ptr<const PMultigridSolver> lower)
  {
    auto       &L           = *levels;
    const auto &lower_L     = *lower->levels;
    const auto &lower_dofs  = *lower_L.dofs[lower_L.dofs.max_level()];
    // Twin meshes: a DoFHandler of the lower degree on this mesh must number as the lower one's.
    DoFHandler<dim> twin(fine_dofs.get_triangulation());
    twin.distribute_dofs(lower_dofs.get_fe());
    if (lower_dofs.get_fe().degree + 1 != fine_dofs.get_fe().degree ||
        !numbered_alike(twin, lower_dofs, communicator))
      return false;

    L.dofs.resize(0, 1);
    L.constraints.resize(0, 1);
    L.operators.resize(0, 1);
    L.dofs[0] = &lower_dofs;
    L.dofs[1] = &fine_dofs;
    L.constraints[0].copy_from(lower_L.constraints[lower_L.constraints.max_level()]);
    level_constraints(fine_dofs, L.constraints[1]);
    L.constraints[1].close();
    L.operators[0] = lower_L.operators[lower_L.operators.max_level()];
    L.operators[1] = std::make_shared<typename Levels::Operator>();
    level_setup(*L.operators[1], *L.mapping, fine_dofs, L.constraints[1]);
    // Twin triangulations have their cells in the same order: the transfer works across them.
    build_transfer();
    L.lower_cycle.lower = std::move(lower);

    const auto &below          = L.lower_cycle.lower->stats;
    stats.largest_aspect_ratio = below.largest_aspect_ratio;
    stats.smoothing_range      = below.smoothing_range;
    stats.smoothing_degree     = below.smoothing_degree;
    stats.coarse_direct        = below.coarse_direct;
    stats.coarse_reused        = true;
    stats.lower_reused         = true;
    stats.long_edge_dofs       = below.long_edge_dofs;
    stats.thick_part_aspect_ratio = below.thick_part_aspect_ratio;
    stats.level_dofs           = below.level_dofs;
    stats.level_dofs.push_back(fine_dofs.n_dofs());
    return true;
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::build_transfer()
  {
    auto &L    = *levels;
    L.transfer = std::make_unique<typename Levels::TransferType>(
      L.dofs, L.constraints, [&L](const unsigned int level, typename Levels::VectorType &vector) {
        L.operators[level]->initialize_dof_vector(vector);
      }, settings.cell_wise_transfer);
  }

  template <int dim, typename Operator>
  std::shared_ptr<DegreeOneLevel> PMultigridSolver<dim, Operator>::degree_one_level() const
  {
    return levels->coarse;
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::build_smoother_and_coarse_solver(const std::vector<double> &fingerprint)
  {
    auto              &L   = *levels;
    const unsigned int top = L.operators.max_level();
    // The V-cycle's objects subscribe to the smoother and the coarse solver about to be replaced.
    L.preconditioner.reset();
    L.multigrid.reset();
    MGLevelObject<typename Levels::SmootherType::AdditionalData> smoother_data(0, top);
    for (unsigned int level = 0; level <= top; ++level)
      {
        auto &data          = smoother_data[level];
        data.preconditioner = std::make_shared<DiagonalMatrix<typename Levels::VectorType>>();
        // Level 0 is solved by the coarse solve, never smoothed: its diagonal only gives the size.
        // (With the long-edge space level 1 is the lowest, smoothed inside its coarse solve.)
        if (level == 0)
          L.operators[level]->initialize_dof_vector(data.preconditioner->get_vector());
        else
          L.operators[level]->compute_inverse_diagonal(data.preconditioner->get_vector());
        data.degree              = stats.smoothing_degree;
        data.smoothing_range     = stats.smoothing_range;
        data.eig_cg_n_iterations = settings.eigenvalue_iterations;
        if (level > 0)
          data.constraints.copy_from(L.constraints[level]);
      }
    L.smoother.initialize(L.operators, smoother_data);

    if (stats.coarse_reused)
      return build_preconditioner();
    if (L.long_edges)
      {
        if (L.long_edge_solve)
          L.long_edge_solve->refactor();
        else
          L.long_edge_solve = std::make_unique<LongEdgeCoarseSolver<dim>>(*L.operators[1], L.smoother, L.long_edges,
                                                                           communicator);
        return build_preconditioner();
      }
    // A new level every time: a solver that reused this one keeps the old.
    auto coarse = std::make_shared<DegreeOneLevel>();
    L.operators[0]->compute_matrix(coarse->matrix, communicator);
    coarse->solver = std::make_unique<CoarseLevelSolver>(coarse->matrix, coarse_rigid_body_modes, dim,
                                                         stats.coarse_direct, settings.coarse_tolerance,
                                                         settings.petsc_options);
    coarse->fingerprint = fingerprint.empty() && L.coarse ? L.coarse->fingerprint : fingerprint;
    coarse->owned       = L.dofs[0]->locally_owned_dofs();
    coarse->direct      = stats.coarse_direct;
    L.coarse            = std::move(coarse);
    build_preconditioner();
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::build_preconditioner()
  {
    auto              &L   = *levels;
    const unsigned int top = L.operators.max_level();
    L.preconditioner.reset();
    L.multigrid.reset();
    L.mg_matrix  = std::make_unique<mg::Matrix<VectorType>>(L.operators);
    L.multigrid  = std::make_unique<Multigrid<VectorType>>(*L.mg_matrix, L.coarse_solve(), *L.transfer, L.smoother,
                                                          L.smoother, L.long_edge_solve ? 1 : 0, top);
    L.preconditioner = std::make_unique<PreconditionMG<dim, VectorType, typename Levels::TransferType>>(
      *L.dofs[top], *L.multigrid, *L.transfer);
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::precondition(VectorType &dst, const VectorType &src) const
  {
    levels->preconditioner->vmult(dst, src);
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::update(const std::function<void(Operator &)> &change)
  {
    Timer timer;
    auto &L = *levels;
    if (L.lower_cycle.lower || (stats.coarse_reused && L.operators.max_level() > 0))
      throw std::logic_error("PMultigridSolver::update: the levels below are another solver's");
    // With the long-edge space level 0 is not used: its state is left as it was.
    for (unsigned int level = L.long_edges ? 1 : L.operators.min_level(); level <= L.operators.max_level(); ++level)
      change(*L.operators[level]);
    // A degree-1 solver (top 0) whose reused level no longer fits the changed operator.
    if (stats.coarse_reused)
      {
        stats.coarse_reused     = false;
        coarse_rigid_body_modes = rigid_body_modes(*L.mapping, *L.dofs[0], communicator);
      }
    build_smoother_and_coarse_solver({});
    stats.setup_seconds += timer.wall_time();
  }

  template <int dim, typename Operator>
  void PMultigridSolver<dim, Operator>::update_fine_operator(const std::function<void(Operator &)> &change)
  {
    Timer timer;
    change(*levels->operators[levels->operators.max_level()]);
    stats.setup_seconds += timer.wall_time();
  }

  template <int dim, typename Operator>
  PMultigridSolver<dim, Operator>::~PMultigridSolver() = default;

  template <int dim, typename Operator>
  unsigned int PMultigridSolver<dim, Operator>::solve(const PETScWrappers::MPI::Vector &condensed_rhs,
                                            const AffineConstraints<double>  &constraints,
                                            PETScWrappers::MPI::Vector        &solution,
                                            const WarmStart                   *start)
  {
    using VectorType        = typename Levels::VectorType;
    auto              &L    = *levels;
    const unsigned int top  = L.operators.max_level();
    const auto        &fine = *L.operators[top];

    // The prescribed values as a conforming field (hanging nodes follow their masters); its
    // action moves to the right-hand side, and CG solves for the correction, zero where prescribed.
    VectorType lifting, rhs, correction, product;
    fine.initialize_dof_vector(lifting);
    fine.initialize_dof_vector(rhs);
    fine.initialize_dof_vector(correction);
    fine.initialize_dof_vector(product);
    constraints.distribute(lifting);
    lifting.update_ghost_values();
    fine.apply_to_lifting(product, lifting);
    const unsigned int n_owned = rhs.locally_owned_size();
    {
      const PetscScalar *values;
      VecGetArrayRead(condensed_rhs, &values);
      for (unsigned int i = 0; i < n_owned; ++i)
        rhs.local_element(i) = values[i] - product.local_element(i);
      VecRestoreArrayRead(condensed_rhs, &values);
    }
    constraints.set_zero(rhs);
    stats.lifted_rhs_norm = rhs.l2_norm();

    const unsigned int coarse_iterations_before = L.coarse_inner_iterations();
    const auto        &preconditioner           = *L.preconditioner;
    double tolerance = settings.relative_tolerance * rhs.l2_norm();
    if (start)
      {
        const PetscScalar *values;
        VecGetArrayRead(start->guess, &values);
        for (unsigned int i = 0; i < n_owned; ++i)
          correction.local_element(i) = values[i];
        VecRestoreArrayRead(start->guess, &values);
        constraints.set_zero(correction); // the prescribed part is the lifting's
        fine.vmult(product, correction);
        product.sadd(-1., 1., rhs);
        stats.initial_residual = product.l2_norm();
        tolerance = std::max(start->reduction * stats.initial_residual, 1e-14 * stats.lifted_rhs_norm);
      }
    else
      stats.initial_residual = stats.lifted_rhs_norm;
    SolverControl        control(settings.max_iterations, tolerance, false, false);
    if (settings.coarse_tolerance > 0 && !stats.coarse_direct)
      SolverFlexibleCG<VectorType>(control).solve(fine, correction, rhs, preconditioner);
    else
      SolverCG<VectorType>(control).solve(fine, correction, rhs, preconditioner);
    stats.coarse_iterations = L.coarse_inner_iterations() - coarse_iterations_before;

    PetscScalar *values;
    VecGetArray(solution, &values);
    for (unsigned int i = 0; i < n_owned; ++i)
      values[i] = correction.local_element(i);
    VecRestoreArray(solution, &values);
    stats.iterations = control.last_step();
    return stats.iterations;
  }

} // namespace compliant::fast_solver

