#include "fast_solver/long_edge_space.h"
#include "linear_algebra/petsc_check.h"

#include <deal.II/base/mpi.h>
#include <deal.II/dofs/dof_accessor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace
  {
    const PetscErrorCheck check("long-edge coarse space");

    // The degree-2 nodes of the reference cell: which directions each is a midpoint in, and its
    // Boolean-sum blend from the nodes with one midpoint direction fewer and below.
    template <int dim>
    struct ReferenceNodes
    {
      std::vector<unsigned int>                                  mid_mask;
      std::vector<std::vector<std::pair<unsigned int, double>>>  blend;
      std::vector<unsigned int>                                  by_mid_count; // node order, vertices first

      explicit ReferenceNodes(const FiniteElement<dim> &scalar_q2)
      {
        const auto        &points = scalar_q2.get_unit_support_points();
        const unsigned int n      = points.size();
        std::vector<unsigned int> code(n), node_of_code(std::pow(3, dim), n);
        mid_mask.assign(n, 0);
        for (unsigned int b = 0; b < n; ++b)
          {
            unsigned int c = 0, stride = 1;
            for (unsigned int d = 0; d < dim; ++d, stride *= 3)
              {
                const unsigned int t = std::lround(2 * points[b][d]); // 0, 1 (midpoint), 2
                c += t * stride;
                if (t == 1)
                  mid_mask[b] |= 1u << d;
              }
            code[b]              = c;
            node_of_code[c]      = b;
          }
        // value(b) = sum over the nodes that keep b's coordinate where b is not a midpoint, are at
        // the midpoint in j of b's k midpoint directions and at 0 or 1 in the others (j < k), of
        // (-1)^(k-1-j) 2^(j-k) times their value.
        blend.resize(n);
        for (unsigned int b = 0; b < n; ++b)
          {
            const unsigned int k = __builtin_popcount(mid_mask[b]);
            for (unsigned int other = 0; other < n; ++other)
              {
                if ((mid_mask[other] & ~mid_mask[b]) != 0 || other == b)
                  continue;
                bool same = true;
                for (unsigned int d = 0, stride = 1; d < dim; ++d, stride *= 3)
                  if (!(mid_mask[b] & (1u << d)) && (code[other] / stride) % 3 != (code[b] / stride) % 3)
                    same = false;
                if (!same)
                  continue;
                const unsigned int j = __builtin_popcount(mid_mask[other]);
                blend[b].emplace_back(other, ((k - 1 - j) % 2 ? -1. : 1.) * std::pow(0.5, k - j));
              }
          }
        by_mid_count.resize(n);
        for (unsigned int b = 0; b < n; ++b)
          by_mid_count[b] = b;
        std::stable_sort(by_mid_count.begin(), by_mid_count.end(), [&](unsigned int a, unsigned int b) {
          return __builtin_popcount(mid_mask[a]) < __builtin_popcount(mid_mask[b]);
        });
      }
    };
  } // namespace

  LongEdgeSpace::~LongEdgeSpace()
  {
    if (prolongation)
      MatDestroy(&prolongation);
  }

  namespace
  {
    // The steps of build_long_edge_space on one DoFHandler.
    template <int dim>
    class Builder
    {
    public:
      Builder(const DoFHandler<dim> &dofs, const AffineConstraints<double> &constraints)
        : dofs(dofs), constraints(constraints), fe(dofs.get_fe()), reference(fe.base_element(0))
        , n_nodes(reference.mid_mask.size()), cell_dofs(fe.n_dofs_per_cell()), system_index(dim * n_nodes)
      {
        // FESystem::component_to_system_index searches its table: look each one up once.
        for (unsigned int c = 0; c < dim; ++c)
          for (unsigned int b = 0; b < n_nodes; ++b)
            system_index[c * n_nodes + b] = fe.component_to_system_index(c, b);
      }

      // The midpoint nodes whose midpoint directions are all long in some cell, by the DoF of
      // their first component: from every cell this rank sees, so that each node of an owned
      // cell has the verdicts of all its cells.
      void mark_free_nodes(const LongCells &long_cells)
      {
        for (const auto &cell : dofs.active_cell_iterators())
          if (!cell->is_artificial())
            {
              const unsigned int mask = long_cells.mask[cell->active_cell_index()];
              if (mask == 0)
                continue;
              cell->get_dof_indices(cell_dofs);
              for (unsigned int b = 0; b < n_nodes; ++b)
                if (reference.mid_mask[b] != 0 && (reference.mid_mask[b] & ~mask) == 0)
                  free_midpoints.insert(dof_of(0, b));
            }
      }

      // The owned free DoFs not held at zero, in order, numbered after the lower ranks'.
      void number_coarse_dofs(LongEdgeSpace &space)
      {
        const IndexSet &owned = dofs.locally_owned_dofs();
        std::vector<types::global_dof_index> coarse;
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(cell_dofs);
              for (unsigned int b = 0; b < n_nodes; ++b)
                if (is_free_node(b))
                  for (unsigned int c = 0; c < dim; ++c)
                    if (owned.is_element(dof_of(c, b)) && !constraints.is_constrained(dof_of(c, b)))
                      coarse.push_back(dof_of(c, b));
            }
        std::sort(coarse.begin(), coarse.end());
        coarse.erase(std::unique(coarse.begin(), coarse.end()), coarse.end());
        const MPI_Comm     comm = dofs.get_communicator();
        unsigned long long n    = coarse.size(), first = 0, owned_free = 0;
        MPI_Exscan(&n, &first, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          first = 0;
        for (const auto g : free_midpoints)
          owned_free += owned.is_element(g);
        space.n_coarse          = Utilities::MPI::sum(n, comm);
        space.n_free_nodes      = Utilities::MPI::sum(owned_free, comm);
        space.n_owned_coarse    = n;
        space.owned_coarse_dofs = coarse;

        DoFTools::extract_locally_relevant_dofs(dofs, relevant);
        coarse_index.reinit(owned, relevant, comm);
        for (std::size_t i = 0; i < coarse.size(); ++i)
          coarse_index(coarse[i]) = first + i + 1.;
        coarse_index.update_ghost_values();
      }

      // P's rows (each owned DoF once) and each owned cell's share of it.
      void fill(LongEdgeSpace &space)
      {
        const IndexSet &owned = dofs.locally_owned_dofs();
        // MPI AIJ on any rank count, like deal.II's PETSc matrices (PETSc multiplies only alike types).
        check(MatCreate(dofs.get_communicator(), &space.prolongation), "MatCreate");
        check(MatSetType(space.prolongation, MATMPIAIJ), "MatSetType(mpiaij)");
        check(MatSetSizes(space.prolongation, owned.n_elements(), space.n_owned_coarse, PETSC_DETERMINE,
                          PETSC_DETERMINE),
              "MatSetSizes");
        check(MatMPIAIJSetPreallocation(space.prolongation, 27, nullptr, 27, nullptr), "MatMPIAIJSetPreallocation");
        check(MatSetOption(space.prolongation, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE), "MatSetOption");
        row_done.assign(owned.n_elements(), false);
        expansion.resize(n_nodes);
        space.cells.clear();
        space.cell_of_active_index.assign(dofs.get_triangulation().n_active_cells(), numbers::invalid_unsigned_int);
        space.neighbour_columns.clear();
        for (const auto &cell : dofs.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(cell_dofs);
              expand_nodes();
              space.cell_of_active_index[cell->active_cell_index()] = space.cells.size();
              add_share(space.cells.emplace_back());
              add_rows(space.prolongation, owned);
            }
          else if (!cell->is_artificial())
            {
              // Another rank's cell at an owned DoF: the coarse DoFs it couples with this rank's.
              cell->get_dof_indices(cell_dofs);
              if (std::none_of(cell_dofs.begin(), cell_dofs.end(), [&](auto g) { return owned.is_element(g); }) ||
                  !std::all_of(cell_dofs.begin(), cell_dofs.end(), [&](auto g) { return relevant.is_element(g); }))
                continue;
              expand_nodes();
              LongEdgeSpace::Cell neighbour;
              add_share(neighbour);
              space.neighbour_columns.push_back(std::move(neighbour.columns));
            }
        check(MatAssemblyBegin(space.prolongation, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
        check(MatAssemblyEnd(space.prolongation, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
      }

    private:
      types::global_dof_index dof_of(const unsigned int component, const unsigned int node) const
      {
        return cell_dofs[system_index[component * n_nodes + node]];
      }
      bool is_free_node(const unsigned int b) const
      {
        return reference.mid_mask[b] == 0 || free_midpoints.count(dof_of(0, b)) > 0;
      }
      // The coarse column of a DoF of the current cell, -1 where it is not coarse.
      PetscInt column_of(const unsigned int component, const unsigned int node) const
      {
        return static_cast<PetscInt>(coarse_index(dof_of(component, node))) - 1;
      }

      // Each node of the current cell in terms of its free nodes, vertices first.
      void expand_nodes()
      {
        for (const unsigned int b : reference.by_mid_count)
          {
            expansion[b].clear();
            if (is_free_node(b))
              {
                expansion[b].emplace_back(b, 1.);
                continue;
              }
            for (const auto &[lower, weight] : reference.blend[b])
              for (const auto &[node, w] : expansion[lower])
                expansion[b].emplace_back(node, weight * w);
          }
      }

      // The cell's share: every DoF not held at zero, in its coarse DoFs, grouped by coarse DoF.
      void add_share(LongEdgeSpace::Cell &share) const
      {
        for (unsigned int b = 0; b < n_nodes; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            if (!constraints.is_constrained(dof_of(c, b)))
              for (const auto &[node, w] : expansion[b])
                {
                  const PetscInt column = column_of(c, node);
                  if (column < 0 || w == 0)
                    continue;
                  auto slot = std::find(share.columns.begin(), share.columns.end(), column);
                  if (slot == share.columns.end())
                    slot = share.columns.insert(slot, column);
                  share.entries.push_back({static_cast<std::uint8_t>(system_index[c * n_nodes + b]),
                                           static_cast<std::uint8_t>(slot - share.columns.begin()),
                                           static_cast<float>(w)});
                }
        // By slot, one entry per (slot, DoF): a DoF reaches a coarse DoF along several blends.
        std::sort(share.entries.begin(), share.entries.end(),
                  [](const auto &a, const auto &b) { return a.slot != b.slot ? a.slot < b.slot : a.dof < b.dof; });
        std::size_t kept = 0;
        for (std::size_t i = 0; i < share.entries.size(); ++i)
          if (kept > 0 && share.entries[kept - 1].slot == share.entries[i].slot &&
              share.entries[kept - 1].dof == share.entries[i].dof)
            share.entries[kept - 1].weight += share.entries[i].weight;
          else
            share.entries[kept++] = share.entries[i];
        share.entries.resize(kept);
        share.slot_begin.assign(share.columns.size() + 1, 0);
        for (const auto &e : share.entries)
          ++share.slot_begin[e.slot + 1];
        for (std::size_t k = 0; k < share.columns.size(); ++k)
          share.slot_begin[k + 1] += share.slot_begin[k];
      }

      // P's rows of the current cell's owned DoFs not yet written (zero rows where held at zero).
      void add_rows(Mat prolongation, const IndexSet &owned)
      {
        for (unsigned int b = 0; b < n_nodes; ++b)
          for (unsigned int c = 0; c < dim; ++c)
            {
              const auto g = dof_of(c, b);
              if (!owned.is_element(g) || row_done[owned.index_within_set(g)])
                continue;
              row_done[owned.index_within_set(g)] = true;
              if (constraints.is_constrained(g))
                continue;
              columns.clear();
              values.clear();
              for (const auto &[node, w] : expansion[b])
                {
                  const PetscInt column = column_of(c, node);
                  if (column < 0 || w == 0)
                    continue;
                  const auto found = std::find(columns.begin(), columns.end(), column);
                  if (found == columns.end())
                    columns.push_back(column), values.push_back(w);
                  else
                    values[found - columns.begin()] += w;
                }
              const PetscInt row = g;
              check(MatSetValues(prolongation, 1, &row, columns.size(), columns.data(), values.data(), INSERT_VALUES),
                    "MatSetValues");
            }
      }

      const DoFHandler<dim>                                     &dofs;
      const AffineConstraints<double>                           &constraints;
      const FiniteElement<dim>                                  &fe;
      const ReferenceNodes<dim>                                  reference;
      const unsigned int                                         n_nodes;
      std::vector<types::global_dof_index>                       cell_dofs;
      std::vector<unsigned int>                                  system_index;
      std::unordered_set<types::global_dof_index>                free_midpoints;
      IndexSet                                                   relevant;
      LinearAlgebra::distributed::Vector<double>                 coarse_index; // column + 1, 0: not coarse
      std::vector<bool>                                          row_done;
      std::vector<std::vector<std::pair<unsigned int, double>>>  expansion;
      std::vector<PetscInt>                                      columns;
      std::vector<PetscScalar>                                   values;
    };
  } // namespace

  template <int dim>
  void build_long_edge_space(const DoFHandler<dim> &dofs, const AffineConstraints<double> &constraints,
                             const LongCells &long_cells, LongEdgeSpace &space)
  {
    const auto &fe = dofs.get_fe();
    if (fe.n_base_elements() != 1 || fe.base_element(0).degree != 2 || fe.n_components() != dim)
      throw std::logic_error("long-edge coarse space: needs dim components of FE_Q(2)");
    Builder<dim> builder(dofs, constraints);
    builder.mark_free_nodes(long_cells);
    builder.number_coarse_dofs(space);
    builder.fill(space);
  }

  template void build_long_edge_space<2>(const DoFHandler<2> &, const AffineConstraints<double> &,
                                         const LongCells &, LongEdgeSpace &);
  template void build_long_edge_space<3>(const DoFHandler<3> &, const AffineConstraints<double> &,
                                         const LongCells &, LongEdgeSpace &);
} // namespace compliant::fast_solver
