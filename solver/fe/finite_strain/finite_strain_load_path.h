// The finite-strain problem as the load-stepping path driver sees it (nonlinear/load_stepping.h).
// The driver runs its own load factor from 0 to 1; `end` maps that onto the problem's, so a path
// can stop at any load factor (buckling about the state there).
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "finite_strain/finite_strain_problem.h"
#include "nonlinear/load_stepping.h"

#include <cmath>
#include <functional>
#include <utility>

namespace compliant
{
  template <int dim>
  class FiniteStrainLoadPath : public LoadPathProblem
  {
  public:
    FiniteStrainLoadPath(FiniteStrainProblem<dim> &problem, std::function<bool()> interruption, double end = 1)
      : problem(problem)
      , interruption(std::move(interruption))
      , end(end)
    {}
    double       load_factor() const override { return problem.load_factor / end; }
    NewtonReport solve_to(const double target) override { return problem.solve_to(target * end); }
    void         save_state() override
    {
      saved             = problem.solution;
      saved_load_factor = problem.load_factor;
      problem.start_contact_step();
    }
    void restore_state() override
    {
      problem.restore(saved, saved_load_factor);
      problem.restore_contact_state();
    }
    double change_from_saved_state() const override
    {
      dealii::PETScWrappers::MPI::Vector change(problem.locally_owned_dofs, problem.communicator);
      change = problem.solution;
      change.add(-1, saved);
      return std::sqrt(problem.unknown_dot(change, change)); // mixed: pressures in length units
    }
    unsigned int unstable_modes() override { return problem.unstable_modes(); }
    bool         stop_requested() override { return interruption && interruption(); }

  private:
    FiniteStrainProblem<dim>          &problem;
    std::function<bool()>              interruption;
    const double                       end;
    dealii::PETScWrappers::MPI::Vector saved;
    double                             saved_load_factor = 0;
  };
} // namespace compliant
