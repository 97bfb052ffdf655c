// How a Newton correction of the finite-strain problem is solved: the matrix-free p-multigrid on
// the tangent (3D, displacement-only, no rigid boundaries or follower pressures) or the assembled
// tangent (MUMPS, or CG + GAMG), and the description the log and the summary give of the choice.
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/numerics/vector_tools.h>

#include "fast_solver/p_multigrid_solver.h"
#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_linear_solver.h"
#include "fast_solver/tangent_operator.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // Vertices of the whole mesh (on a distributed mesh those on rank boundaries count twice).
    template <int dim>
    std::size_t n_global_vertices(const parallel::TriangulationBase<dim> &triangulation)
    {
      if (dynamic_cast<const parallel::shared::Triangulation<dim> *>(&triangulation))
        return triangulation.n_vertices();
      const auto owned = GridTools::get_locally_owned_vertices(triangulation);
      return Utilities::MPI::sum<std::size_t>(std::count(owned.begin(), owned.end(), true),
                                              triangulation.get_communicator());
    }
  } // namespace

  template <int dim>
  bool FiniteStrainProblem<dim>::matrix_free_tangent() const
  {
    const SolverMethod method = parameters.solver_method;
    // auto: measured on cases/benchmarks/flexure_finite_strain.prm (2 ranks, OpenBLAS, MUMPS
    // LDL^T on a kept analysis), the p-multigrid's time_total against MUMPS's: 0.19 / 0.16 s at
    // 585 DoFs, 0.20 / 0.25 at 945, 0.38 / 0.93 at 3.3k (reduced integration 0.72 / 1.00), 0.79 /
    // 1.81 at 7.1k, 2.6 / 7.6 at 20.7k: the tangent's assembly is what MUMPS pays beyond its
    // factorization. MUMPS stays on 2D models (2D elastica, 2k DoFs: 0.4 s of solves against 0.8 s).
    const bool wanted = method == SolverMethod::matrix_free ||
                        (method == SolverMethod::automatic && dim == 3 && dof_handler.n_dofs() >= auto_matrix_free_dofs);
    return wanted && !iterative_failed && !mixed && follower_pressures.empty() &&
           rigid_boundaries.empty() && !contact && settings.extra.empty() && fe->degree >= 2;
  }

  template <int dim>
  std::string FiniteStrainProblem<dim>::linear_solver_description() const
  {
    const SolverMethod method = parameters.solver_method;
    std::string        why;
    if (method == SolverMethod::direct)
      why = "asked for";
    else if (mixed)
      why = "the mixed u-p tangent is indefinite";
    else if (!follower_pressures.empty())
      why = "a follower pressure makes the tangent unsymmetric";
    else if (!rigid_boundaries.empty())
      why = "a rigid boundary ties its nodes together (the multigrid levels cannot)";
    else if (contact)
      why = "contact constraints change with the active set (the multigrid levels do not hold them)";
    else if (!settings.extra.empty())
      why = "pins, mirror ties or edge supports tie DoFs the multigrid levels do not hold";
    else if (fe->degree < 2 && method != SolverMethod::cg_amg)
      why = "degree 1 has no p-multigrid levels";
    else if (method == SolverMethod::automatic)
      why = "2D or fewer than " + std::to_string(auto_matrix_free_dofs) +
            " DoFs, where the factorization is cheaper";
    if (!iterative_failure.empty())
      return (method == SolverMethod::cg_amg ? std::string("CG + GAMG") : std::string("matrix-free p-multigrid")) +
             " until it failed (" + iterative_failure + "), then direct (MUMPS)";
    if (matrix_free_tangent())
      return "matrix-free p-multigrid on the Newton tangent (Davydov et al. 2020)";
    if (method == SolverMethod::cg_amg && dim == 3 && !rigid_boundaries.empty())
      return "direct (MUMPS) on the assembled tangent: a rigid boundary's tangent is unsymmetric in 3D";
    if (method == SolverMethod::cg_amg && !mixed)
      return "CG + GAMG on the assembled tangent";
    return "direct (MUMPS) on the assembled tangent" + (why.empty() ? std::string() : ": " + why);
  }

  template <int dim>
  bool FiniteStrainProblem<dim>::symmetric_tangent() const
  {
    // A follower pressure, a moment on a rigid boundary in 3D and friction make it unsymmetric.
    return follower_pressures.empty() && !(dim == 3 && !rigid_boundaries.empty()) && !contact;
  }

  template <int dim>
  void FiniteStrainProblem<dim>::solve_direct(PETScWrappers::MPI::Vector &du, const PETScWrappers::MPI::Vector &rhs)
  {
    // Measured on cases/benchmarks/flexure_finite_strain.prm at 20 x 4 x 1 cells (3.3k DoFs, 30
    // Newton iterations, 2 ranks, OpenBLAS): a fresh LU each iteration took 19 ms, the kept LDL^T 11 ms.
    if (!newton_factorization)
      {
        insert_petsc_options(parameters.petsc_options);
        newton_factorization = std::make_shared<DirectFactorization>();
      }
    newton_factorization->factor(tangent, symmetric_tangent(), true, false);
    newton_factorization->solve(du, rhs);
  }

  template <int dim>
  void FiniteStrainProblem<dim>::add_level_constraints(const DoFHandler<dim>     &dofs,
                                                       AffineConstraints<double> &constraints) const
  {
    // The homogeneous counterpart of make_constraints on any degree's DoFs (displacement-only).
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    const Functions::ZeroFunction<dim> zero(dim);
    for (const auto &[name, id] : boundary_conditions.clamped)
      VectorTools::interpolate_boundary_values(*mapping, dofs, id, zero, constraints);
    for (const auto &d : boundary_conditions.displacements)
      {
        std::vector<bool> mask(dim);
        for (unsigned int c = 0; c < dim; ++c)
          mask[c] = d.mask[c];
        VectorTools::interpolate_boundary_values(*mapping, dofs, d.boundary_id, zero, constraints,
                                                 ComponentMask(mask));
      }
    for (const auto &r : boundary_conditions.rotations)
      VectorTools::interpolate_boundary_values(*mapping, dofs, r.boundary_id, zero, constraints);
  }

  template <int dim>
  unsigned int FiniteStrainProblem<dim>::solve_matrix_free(const PETScWrappers::MPI::Vector &u,
                                                           const PETScWrappers::MPI::Vector &rhs,
                                                           const AffineConstraints<double>  &constraints,
                                                           PETScWrappers::MPI::Vector       &du)
  {
    using Operator = fast_solver::TangentOperator<dim, double>;
    const fast_solver::PointResponse<dim> response =
      [this](const types::material_id id, const Tensor<2, dim> &grad_u, SymmetricTensor<2, dim> &S,
             SymmetricTensor<4, dim> &dS_dE) {
        const auto r = material_response(laws.at(id), green_lagrange(grad_u), 0.0);
        S            = thickness * r.S;
        dS_dE        = thickness * r.tangent;
      };
    const auto set_state = [&](Operator &level_operator) {
      level_operator.set_state(dof_handler, u, response);
    };
    Timer setup_timer;
    // The preconditioner is rebuilt (every level's state, diagonals, eigenvalue estimates, the
    // degree-1 factorization) only when the last solve with an older one converged much slower
    // than right after a rebuild; otherwise only the finest operator takes the new state.
    bool fresh = true;
    if (!tangent_multigrid)
      {
        fast_solver::PMultigridSettings settings;
        settings.max_iterations     = 300;
        settings.petsc_options      = parameters.petsc_options;
        settings.long_edge_space    = parameters.long_edge_coarse_space;
        // The tangent turns with the structure, so the reference rigid-body modes GAMG would be
        // given are only approximate: factor the degree-1 level while it is small.
        if (dim * n_global_vertices(triangulation) <=
            (dim == 3 ? settings.direct_coarse_limit_3d : settings.direct_coarse_limit))
          settings.coarse = fast_solver::PMultigridSettings::Coarse::direct;
        tangent_multigrid = std::make_unique<TangentMultigrid>(
          *mapping, dof_handler,
          [this](const DoFHandler<dim> &dofs, AffineConstraints<double> &level_constraints) {
            IndexSet relevant;
            DoFTools::extract_locally_relevant_dofs(dofs, relevant);
            level_constraints.reinit(relevant);
            add_level_constraints(dofs, level_constraints);
          },
          [&](Operator &level_operator, const Mapping<dim> &level_mapping, const DoFHandler<dim> &dofs,
              const AffineConstraints<double> &level_constraints) {
            // Integration = reduced: every level of degree >= 2 as the residual (degree 1 stays full).
            level_operator.reinit(level_mapping, dofs, level_constraints,
                                  parameters.reduced_integration ? parameters.hourglass_stiffness : -1.);
            set_state(level_operator);
          },
          settings, communicator);
        const auto &s = tangent_multigrid->statistics();
        if (Utilities::MPI::this_mpi_process(communicator) == 0)
          std::cout << "Linear solver: matrix-free p-multigrid on the tangent (largest cell aspect "
                    << "ratio " << std::setprecision(3) << s.largest_aspect_ratio << ": Chebyshev degree "
                    << s.smoothing_degree << " over range " << s.smoothing_range << ", "
                    << fast_solver::coarse_level_note(s) << ")" << std::setprecision(6) << std::endl;
      }
    else if (preconditioner_stale)
      tangent_multigrid->update(set_state);
    else
      {
        tangent_multigrid->update_fine_operator(set_state);
        fresh = false;
      }
    preconditioner_setup_seconds += setup_timer.wall_time();
    // Newton's forcing term, but never looser than 0.1 nor tighter than 1e-8, which keeps the
    // quadratic convergence down to the Newton tolerance (1e-9 of the force scale).
    const double tolerance = std::clamp(linear_forcing, 1e-8, 0.1);
    tangent_multigrid->set_relative_tolerance(tolerance);
    const auto solve = [&]() {
      try
        {
          return tangent_multigrid->solve(rhs, constraints, du);
        }
      catch (const SolverControl::NoConvergence &e)
        {
          throw std::runtime_error("CG did not converge in " + std::to_string(e.last_step) +
                                   " iterations (residual " + std::to_string(e.last_residual) + ")");
        }
    };
    unsigned int iterations = 0;
    try
      {
        iterations = solve();
      }
    catch (const std::runtime_error &)
      {
        if (fresh)
          throw;
        // A preconditioner of an older state may not fit at all any more: rebuild it once.
        Timer rebuild_timer;
        tangent_multigrid->update(set_state);
        preconditioner_setup_seconds += rebuild_timer.wall_time();
        fresh      = true;
        du         = 0;
        iterations = solve();
      }
    const double rate = iterations / std::max(1.0, -std::log10(tolerance));
    if (fresh)
      {
        ++preconditioner_builds;
        preconditioner_rate = rate;
      }
    preconditioner_stale = !fresh && rate > lagged_preconditioner_slowdown * preconditioner_rate + 1;
    return iterations;
  }

  template bool FiniteStrainProblem<2>::matrix_free_tangent() const;
  template bool FiniteStrainProblem<3>::matrix_free_tangent() const;
  template std::string FiniteStrainProblem<2>::linear_solver_description() const;
  template bool FiniteStrainProblem<2>::symmetric_tangent() const;
  template bool FiniteStrainProblem<3>::symmetric_tangent() const;
  template void FiniteStrainProblem<2>::solve_direct(PETScWrappers::MPI::Vector &, const PETScWrappers::MPI::Vector &);
  template void FiniteStrainProblem<3>::solve_direct(PETScWrappers::MPI::Vector &, const PETScWrappers::MPI::Vector &);
  template std::string FiniteStrainProblem<3>::linear_solver_description() const;
  template void FiniteStrainProblem<2>::add_level_constraints(const DoFHandler<2> &, AffineConstraints<double> &) const;
  template void FiniteStrainProblem<3>::add_level_constraints(const DoFHandler<3> &, AffineConstraints<double> &) const;
  template unsigned int FiniteStrainProblem<2>::solve_matrix_free(const PETScWrappers::MPI::Vector &,
                                                                  const PETScWrappers::MPI::Vector &,
                                                                  const AffineConstraints<double> &,
                                                                  PETScWrappers::MPI::Vector &);
  template unsigned int FiniteStrainProblem<3>::solve_matrix_free(const PETScWrappers::MPI::Vector &,
                                                                  const PETScWrappers::MPI::Vector &,
                                                                  const AffineConstraints<double> &,
                                                                  PETScWrappers::MPI::Vector &);
} // namespace compliant
