#include "elasticity/global_constraints.h"

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/sparsity_tools.h>

#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  AffineConstraints<double> gather_constraints(const LinearElasticProblem<dim> &problem,
                                               const bool                       homogeneous)
  {
    using Line = AffineConstraints<double>::ConstraintLine;
    // Each line once, from the rank that owns its DoF (ghost copies are identical).
    std::vector<Line> owned_lines;
    for (const auto &line : problem.constraints.get_lines())
      if (problem.locally_owned_dofs.is_element(line.index))
        owned_lines.push_back(line);
    const auto all_lines = Utilities::MPI::all_gather(problem.communicator, owned_lines);

    AffineConstraints<double> constraints(complete_index_set(problem.dof_handler.n_dofs()));
    for (const auto &lines : all_lines)
      for (const auto &line : lines)
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
          if (!homogeneous)
            constraints.set_inhomogeneity(line.index, line.inhomogeneity);
        }
    return constraints;
  }

  template <int dim>
  DynamicSparsityPattern install_constraints(LinearElasticProblem<dim>   &problem,
                                             AffineConstraints<double> &&constraints)
  {
    constraints.close();
    problem.require_assembled_matrix("pins, mirror ties or edge supports");
    problem.constraints = std::move(constraints);
    problem.constraints_gathered = true;
    const auto             n_dofs = problem.dof_handler.n_dofs();
    DynamicSparsityPattern dsp(n_dofs, n_dofs);
    DoFTools::make_sparsity_pattern(problem.dof_handler, dsp, problem.constraints, false);
    // Condensing a tie adds couplings to rows that other ranks own: send every such row.
    SparsityTools::distribute_sparsity_pattern(dsp, problem.locally_owned_dofs,
                                               problem.communicator, complete_index_set(n_dofs));
    problem.system_matrix.reinit(problem.locally_owned_dofs, problem.locally_owned_dofs, dsp,
                                 problem.communicator);
    return dsp;
  }

  template AffineConstraints<double> gather_constraints<2>(const LinearElasticProblem<2> &, bool);
  template AffineConstraints<double> gather_constraints<3>(const LinearElasticProblem<3> &, bool);
  template DynamicSparsityPattern install_constraints<2>(LinearElasticProblem<2> &,
                                                         AffineConstraints<double> &&);
  template DynamicSparsityPattern install_constraints<3>(LinearElasticProblem<3> &,
                                                         AffineConstraints<double> &&);
} // namespace compliant
