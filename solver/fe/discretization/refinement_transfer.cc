#include "discretization/refinement_transfer.h"

#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace compliant
{
  namespace
  {
    // The active coarse cell that `parent` (a cell of the refined mesh) was built from: the same
    // coarse-mesh cell and child path, and the same vertices. End iterator where there is none.
    // The coarse mesh must be whole on this rank.
    template <int dim>
    typename dealii::DoFHandler<dim>::cell_iterator
    coarse_twin_of(const typename dealii::Triangulation<dim>::cell_iterator &parent,
                   const dealii::DoFHandler<dim>                             &coarse_dofs)
    {
      const auto &tria = coarse_dofs.get_triangulation();
      const auto  none = coarse_dofs.end();
      // The path from the coarse-mesh cell down to `parent`.
      std::vector<unsigned int> path;
      auto                      walk = parent;
      for (; walk->level() > 0; walk = walk->parent())
        path.push_back(walk->parent()->child_iterator_to_index(walk));
      // A distributed fine mesh numbers its coarse cells locally: go by the global coarse-cell
      // id, which on the (shared) coarse mesh is the coarse cell's index.
      const auto coarse_cell_id = walk->id().get_coarse_cell_id();
      if (coarse_cell_id >= tria.n_cells(0))
        return none;
      typename dealii::Triangulation<dim>::cell_iterator cell(&tria, 0, coarse_cell_id);
      for (auto step = path.rbegin(); step != path.rend(); ++step)
        {
          if (!cell->has_children() || *step >= cell->n_children())
            return none;
          cell = cell->child(*step);
        }
      if (cell->has_children() || cell->n_vertices() != parent->n_vertices())
        return none;
      for (unsigned int v = 0; v < cell->n_vertices(); ++v)
        if (cell->vertex(v).distance(parent->vertex(v)) > 1e-10 * cell->diameter())
          return none;
      return typename dealii::DoFHandler<dim>::cell_iterator(&tria, cell->level(), cell->index(), &coarse_dofs);
    }
  } // namespace

  template <int dim>
  bool build_refinement_prolongation(const Discretization<dim>               &coarse,
                                     const Discretization<dim>               &fine,
                                     const dealii::AffineConstraints<double> &fine_constraints,
                                     dealii::PETScWrappers::MPI::SparseMatrix &prolongation)
  {
    // The coarse mesh whole on every rank (shared): the fine mesh may then be distributed.
    using Shared   = dealii::parallel::shared::Triangulation<dim>;
    const auto *cs = dynamic_cast<const Shared *>(&coarse.triangulation);
    const auto &fe = *fine.fe;
    bool        twins = cs && !cs->with_artificial_cells() &&
                 fe.get_name() == coarse.fe->get_name() &&
                 fine.triangulation.n_global_active_cells() > coarse.triangulation.n_global_active_cells();
    const unsigned int n = fe.n_dofs_per_cell();
    std::vector<dealii::types::global_dof_index> fine_indices(n), coarse_indices(n);
    std::vector<std::tuple<dealii::types::global_dof_index, dealii::types::global_dof_index, double>> entries;
    std::vector<bool>              row_done(fine.locally_owned_dofs.n_elements(), false);
    dealii::DynamicSparsityPattern pattern(fine.dof_handler.n_dofs(), coarse.dof_handler.n_dofs(),
                                           fine.locally_owned_dofs);
    // Every owned DoF lies on an owned cell; its row is the same from each of its cells: set once.
    for (auto cell = fine.dof_handler.begin_active(); twins && cell != fine.dof_handler.end(); ++cell)
      {
        if (!cell->is_locally_owned()) // a distributed mesh's other cells may be coarser
          continue;
        if (cell->level() == 0)
          {
            twins = false;
            break;
          }
        const auto parent = cell->parent();
        const auto twin   = coarse_twin_of<dim>(parent, coarse.dof_handler);
        if (twin == coarse.dof_handler.end() || parent->refinement_case() != dealii::RefinementCase<dim>::isotropic_refinement)
          {
            twins = false;
            break;
          }
        cell->get_dof_indices(fine_indices);
        twin->get_dof_indices(coarse_indices);
        const auto &local = fe.get_prolongation_matrix(parent->child_iterator_to_index(cell), parent->refinement_case());
        for (unsigned int i = 0; i < n; ++i)
          if (fine.locally_owned_dofs.is_element(fine_indices[i]) && !fine_constraints.is_constrained(fine_indices[i]) &&
              !row_done[fine.locally_owned_dofs.index_within_set(fine_indices[i])])
            for (unsigned int j = 0; j < n; ++j)
              if (std::abs(local(i, j)) > 1e-13)
                {
                  pattern.add(fine_indices[i], coarse_indices[j]);
                  entries.emplace_back(fine_indices[i], coarse_indices[j], local(i, j));
                  row_done[fine.locally_owned_dofs.index_within_set(fine_indices[i])] = true;
                }
      }
    twins = dealii::Utilities::MPI::min(twins ? 1 : 0, fine.communicator) == 1;
    if (!twins)
      return false;
    prolongation.reinit(fine.locally_owned_dofs, coarse.locally_owned_dofs, pattern, fine.communicator);
    for (const auto &[i, j, value] : entries)
      prolongation.set(i, j, value);
    prolongation.compress(dealii::VectorOperation::insert);
    return true;
  }

  template bool build_refinement_prolongation<2>(const Discretization<2> &, const Discretization<2> &,
                                                 const dealii::AffineConstraints<double> &,
                                                 dealii::PETScWrappers::MPI::SparseMatrix &);
  template bool build_refinement_prolongation<3>(const Discretization<3> &, const Discretization<3> &,
                                                 const dealii::AffineConstraints<double> &,
                                                 dealii::PETScWrappers::MPI::SparseMatrix &);
} // namespace compliant
