// The matrix pattern of a problem with rigid boundaries: a boundary's masters are chosen anew at
// every linearization among a few candidate DoFs, so the pattern holds every coupling any choice
// can condense onto.
#include "constraints/rigid_boundary.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/sparsity_tools.h>

#include <algorithm>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  void RigidBoundary<dim>::add_candidate_couplings(const DoFHandler<dim>  &dofs,
                                                   DynamicSparsityPattern &pattern) const
  {
    std::vector<types::global_dof_index> indices;
    for (const unsigned int c : candidates)
      indices.push_back(boundary_dofs[c].index);
    std::vector<types::global_dof_index> cell_dofs(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(cell_dofs);
          const bool touches = std::any_of(cell_dofs.begin(), cell_dofs.end(), [&](const auto i) {
            return std::find(indices.begin(), indices.end(), i) != indices.end();
          });
          if (!touches)
            continue;
          for (const auto candidate : indices)
            for (const auto j : cell_dofs)
              {
                pattern.add(candidate, j);
                pattern.add(j, candidate);
              }
        }
    for (const auto a : indices)
      for (const auto b : indices)
        pattern.add(a, b);
  }

  template <int dim>
  void reinit_matrix(PETScWrappers::MPI::SparseMatrix &matrix, const DoFHandler<dim> &dofs,
                     const AffineConstraints<double> &constraints, const std::vector<RigidBoundary<dim>> &rigid_boundaries,
                     const IndexSet &owned, const IndexSet &relevant, MPI_Comm communicator,
                     const bool keep_constrained)
  {
    // Rows of a rigid boundary's masters get entries from every cell on that boundary.
    IndexSet rows = relevant;
    for (const auto &rigid : rigid_boundaries)
      rows.add_indices(rigid.master_candidates(dofs.n_dofs()));
    // So do the DoFs a constraint line refers to beyond this rank's (contact between boundaries:
    // a master surface's nodes anywhere).
    std::vector<types::global_dof_index> referred;
    for (const auto &line : constraints.get_lines())
      for (const auto &entry : line.entries)
        if (!rows.is_element(entry.first))
          referred.push_back(entry.first);
    std::sort(referred.begin(), referred.end());
    referred.erase(std::unique(referred.begin(), referred.end()), referred.end());
    rows.add_indices(referred.begin(), referred.end());
    DynamicSparsityPattern pattern(rows);
    DoFTools::make_sparsity_pattern(dofs, pattern, constraints, keep_constrained);
    for (const auto &rigid : rigid_boundaries)
      rigid.add_candidate_couplings(dofs, pattern);
    SparsityTools::distribute_sparsity_pattern(pattern, owned, communicator, rows);
    matrix.reinit(owned, owned, pattern, communicator);
  }

  template void RigidBoundary<2>::add_candidate_couplings(const DoFHandler<2> &, DynamicSparsityPattern &) const;
  template void RigidBoundary<3>::add_candidate_couplings(const DoFHandler<3> &, DynamicSparsityPattern &) const;
  template void reinit_matrix(PETScWrappers::MPI::SparseMatrix &, const DoFHandler<2> &, const AffineConstraints<double> &,
                              const std::vector<RigidBoundary<2>> &, const IndexSet &, const IndexSet &, MPI_Comm, bool);
  template void reinit_matrix(PETScWrappers::MPI::SparseMatrix &, const DoFHandler<3> &, const AffineConstraints<double> &,
                              const std::vector<RigidBoundary<3>> &, const IndexSet &, const IndexSet &, MPI_Comm, bool);
} // namespace compliant
