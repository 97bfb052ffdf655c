// Extra constraints at finite strain: pins, mirror ties and edge supports (constraints/), the
// same lines as in the linear analyses, on the displacements. Mirror ties and edge supports are
// exact at any strain (a mirror image of a displacement field is linear in it; a component held
// at zero stays held). A pin's radial ties keep the radial directions of the reference
// configuration: exact while the joint turns little, off by r (1 - cos theta), about r theta^2 / 2,
// where an eye of radius r has turned by theta on its pin (a mechanism turning about its joints
// needs the ties to turn with it). The lines are made once, against the supports, and added to
// every make_constraints; every rank then keeps every line (a pin ties DoFs of bodies any ranks
// own, and a clamped pin's lines must be where its eyes' are for the chains to close).
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/distributed/shared_tria.h>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  void FiniteStrainProblem<dim>::set_up_extra_constraints()
  {
    extra_lines.clear();
    extra_dofs = IndexSet(dof_handler.n_dofs());
    if (settings.extra.empty())
      return;
    // The pins' nodes are found on every cell (constraints/boundary_dof_points.h).
    if (dynamic_cast<const parallel::shared::Triangulation<dim> *>(&triangulation) == nullptr)
      throw std::invalid_argument("Extra constraints: pins, mirror ties and edge supports need the whole mesh on "
                                  "every rank; Discretization/Mesh partition = distributed cannot hold them");
    const PETScWrappers::MPI::Vector zero(locally_owned_dofs, locally_relevant_dofs, communicator);
    AffineConstraints<double>        supports = make_constraints(0, true, zero); // no extra lines yet
    AffineConstraints<double>        with_extra(supports.get_local_lines());
    with_extra.merge(supports);
    add_extra_constraints(*this, settings.extra, with_extra);
    for (const auto &line : with_extra.get_lines())
      if (!supports.is_constrained(line.index))
        {
          extra_lines.push_back(line);
          extra_dofs.add_index(line.index);
          for (const auto &entry : line.entries)
            extra_dofs.add_index(entry.first);
        }
    extra_dofs.compress();
  }

  template <int dim>
  void FiniteStrainProblem<dim>::add_extra_lines(AffineConstraints<double> &constraints) const
  {
    for (const auto &line : extra_lines)
      if (!constraints.is_constrained(line.index))
        {
          constraints.add_line(line.index);
          constraints.add_entries(line.index, line.entries);
        }
  }

  template <int dim>
  void FiniteStrainProblem<dim>::state_for_constraints(const PETScWrappers::MPI::Vector &u,
                                                       PETScWrappers::MPI::Vector       &state) const
  {
    PETScWrappers::MPI::Vector owned(locally_owned_dofs, communicator);
    owned           = u;
    IndexSet ghosts = locally_relevant_dofs;
    ghosts.add_indices(extra_dofs);
    state.reinit(locally_owned_dofs, ghosts, communicator);
    state = owned;
  }

  template void FiniteStrainProblem<2>::set_up_extra_constraints();
  template void FiniteStrainProblem<3>::set_up_extra_constraints();
  template void FiniteStrainProblem<2>::add_extra_lines(AffineConstraints<double> &) const;
  template void FiniteStrainProblem<3>::add_extra_lines(AffineConstraints<double> &) const;
  template void FiniteStrainProblem<2>::state_for_constraints(const PETScWrappers::MPI::Vector &,
                                                              PETScWrappers::MPI::Vector &) const;
  template void FiniteStrainProblem<3>::state_for_constraints(const PETScWrappers::MPI::Vector &,
                                                              PETScWrappers::MPI::Vector &) const;
} // namespace compliant
