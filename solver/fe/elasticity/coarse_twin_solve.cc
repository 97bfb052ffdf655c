// The error estimates' once-refined model solved from its unrefined twin: two-level CG whose
// coarse level is the twin's MUMPS factor (linear_algebra/two_level_solver.h).
#include "discretization/refinement_transfer.h"
#include "elasticity/linear_elastic_problem.h"
#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/two_level_solver.h"

#include <sstream>


namespace compliant
{
  using namespace dealii;

  template <int dim>
  bool LinearElasticProblem<dim>::solve_from_coarse_twin(PETScWrappers::MPI::Vector &x)
  {
    if (!coarse_twin || !coarse_twin->factorization || solver_method == SolverMethod::matrix_free)
      return false;
    PETScWrappers::MPI::SparseMatrix prolongation;
    if (!build_refinement_prolongation<dim>(*coarse_twin, *this, constraints, prolongation))
      {
        solver_note += (solver_note.empty() ? "" : "; ") +
                       std::string("the unrefined model's factor not used: the meshes are not twins "
                                   "(a distributed mesh, or another refinement)");
        return false;
      }
    // The start: the unrefined model's solution carried here, the prescribed values set exactly.
    PETScWrappers::MPI::Vector coarse_solution(coarse_twin->locally_owned_dofs, communicator);
    coarse_solution = coarse_twin->solution;
    prolongation.vmult(x, coarse_solution);
    constraints.distribute(x);

    TwoLevelSystem system{&system_matrix, &prolongation, &coarse_twin->system_matrix,
                          coarse_twin->factorization.get(), {}};
    for (const auto &line : coarse_twin->constraints.get_lines())
      if (coarse_twin->locally_owned_dofs.is_element(line.index))
        system.coarse_constrained.push_back(line.index);
    try
      {
        const auto result           = solve_two_level(system, system_rhs, x, warm_start_reduction, 200);
        statistics.iterations       = result.iterations;
        statistics.initial_residual = result.initial_residual;
      }
    catch (const std::runtime_error &e)
      {
        solver_note += (solver_note.empty() ? "" : "; ") + std::string(e.what()) + ": solved as before";
        x = 0;
        return false;
      }
    std::ostringstream note;
    note << "two-level CG from the unrefined model's solution (symmetric Gauss-Seidel smoothing, that model's "
            "MUMPS factor below) to a residual reduction of "
         << warm_start_reduction;
    solver_note = note.str();
    return true;
  }

  template bool LinearElasticProblem<2>::solve_from_coarse_twin(PETScWrappers::MPI::Vector &);
  template bool LinearElasticProblem<3>::solve_from_coarse_twin(PETScWrappers::MPI::Vector &);
} // namespace compliant
