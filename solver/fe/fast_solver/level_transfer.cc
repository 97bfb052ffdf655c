#include "fast_solver/level_transfer.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_tools.h>

#include <algorithm>
#include <vector>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace
  {
    // Whether every constraint only holds a DoF at zero (no DoF follows others).
    bool only_held_at_zero(const AffineConstraints<double> &constraints)
    {
      for (const auto &line : constraints.get_lines())
        if (!line.entries.empty() || line.inhomogeneity != 0.)
          return false;
      return true;
    }
  } // namespace

  // One level's transfer. Per locally owned cell and vector component, the local indices of the
  // fine and the coarse DoFs in scalar-element order; `skip` where the cell does not write a fine
  // DoF (another cell does, another rank owns it, or it is held) or reads a held coarse DoF as 0.
  template <int dim>
  struct LevelTransfer<dim>::CellWise
  {
    static constexpr unsigned int skip = numbers::invalid_unsigned_int;
    // The 1D interpolation (fine points x coarse points, lexicographic): the cell's is its
    // tensor product, applied one direction at a time.
    std::vector<double>           interpolation;
    unsigned int                  points_fine = 0, points_coarse = 0, n_fine = 0, n_coarse = 0;
    std::vector<unsigned int>     fine, coarse; // per cell: dim * n_fine, dim * n_coarse, lexicographic
    mutable VectorType            coarse_ghosted;
    mutable std::vector<double>   buffer[3];

    // out = (M x ... x M) in, or its transpose, M = interpolation.
    void apply_tensor(const bool transpose, const double *in, double *out) const
    {
      const unsigned int rows = transpose ? points_coarse : points_fine;
      const unsigned int cols = transpose ? points_fine : points_coarse;
      const double      *from = in;
      for (unsigned int d = 0; d < dim; ++d)
        {
          double      *to = d + 1 == dim ? out : buffer[d % 2].data();
          unsigned int before = 1, after = 1;
          for (unsigned int e = 0; e < d; ++e)
            before *= rows;
          for (unsigned int e = d + 1; e < dim; ++e)
            after *= cols;
          for (unsigned int a = 0; a < after; ++a)
            for (unsigned int r = 0; r < rows; ++r)
              for (unsigned int b = 0; b < before; ++b)
                {
                  double sum = 0;
                  for (unsigned int c = 0; c < cols; ++c)
                    sum += (transpose ? interpolation[c * points_coarse + r] : interpolation[r * points_coarse + c]) *
                           from[(a * cols + c) * before + b];
                  to[(a * rows + r) * before + b] = sum;
                }
          from = to;
        }
    }

    // False if the two meshes' cells differ, or a coarse DoF lies outside the coarse layout.
    bool reinit(const DoFHandler<dim> &fine_dofs, const DoFHandler<dim> &coarse_dofs,
                const AffineConstraints<double> &fine_constraints,
                const AffineConstraints<double> &coarse_constraints, const VectorType &fine_layout,
                const VectorType &coarse_layout)
    {
      const auto &fine_fe = fine_dofs.get_fe(), &coarse_fe = coarse_dofs.get_fe();
      if (fine_fe.n_components() != dim || coarse_fe.n_components() != dim || fine_fe.n_base_elements() != 1 ||
          coarse_fe.n_base_elements() != 1)
        return false;
      const unsigned int fine_degree = fine_fe.base_element(0).degree, coarse_degree = coarse_fe.base_element(0).degree;
      // FE_Q with its own (Gauss-Lobatto) points only: the 1D matrix below is built for them.
      const auto is_plain_q = [](const FiniteElement<dim> &base) {
        return dynamic_cast<const FE_Q<dim> *>(&base) != nullptr &&
               base.get_unit_support_points() == FE_Q<dim>(base.degree).get_unit_support_points();
      };
      if (!is_plain_q(fine_fe.base_element(0)) || !is_plain_q(coarse_fe.base_element(0)))
        return false;
      points_fine   = fine_degree + 1;
      points_coarse = coarse_degree + 1;
      n_fine        = Utilities::pow(points_fine, dim);
      n_coarse      = Utilities::pow(points_coarse, dim);
      {
        const FE_Q<1> fine_1d(fine_degree), coarse_1d(coarse_degree);
        const auto    fine_order   = FETools::lexicographic_to_hierarchic_numbering<1>(fine_degree);
        const auto    coarse_order = FETools::lexicographic_to_hierarchic_numbering<1>(coarse_degree);
        interpolation.resize(points_fine * points_coarse);
        for (unsigned int r = 0; r < points_fine; ++r)
          for (unsigned int c = 0; c < points_coarse; ++c)
            interpolation[r * points_coarse + c] =
              coarse_1d.shape_value(coarse_order[c], fine_1d.get_unit_support_points()[fine_order[r]]);
      }
      for (auto &b : buffer)
        b.resize(Utilities::pow(std::max(points_fine, points_coarse), dim));
      const auto fine_lexicographic   = FETools::hierarchic_to_lexicographic_numbering<dim>(fine_degree);
      const auto coarse_lexicographic = FETools::hierarchic_to_lexicographic_numbering<dim>(coarse_degree);
      coarse_ghosted.reinit(coarse_layout.get_partitioner());
      const auto &fine_partitioner   = *fine_layout.get_partitioner();
      const auto &coarse_partitioner = *coarse_layout.get_partitioner();

      std::vector<bool>                    written(fine_partitioner.locally_owned_size(), false);
      std::vector<types::global_dof_index> fine_indices(fine_fe.n_dofs_per_cell()),
        coarse_indices(coarse_fe.n_dofs_per_cell());
      auto coarse_cell = coarse_dofs.begin_active();
      for (const auto &cell : fine_dofs.active_cell_iterators())
        {
          if (coarse_cell == coarse_dofs.end() || coarse_cell->level() != cell->level() ||
              coarse_cell->index() != cell->index() || coarse_cell->is_locally_owned() != cell->is_locally_owned())
            return false;
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(fine_indices);
              coarse_cell->get_dof_indices(coarse_indices);
              const std::size_t first_fine = fine.size(), first_coarse = coarse.size();
              fine.resize(first_fine + dim * n_fine, skip);
              coarse.resize(first_coarse + dim * n_coarse, skip);
              for (unsigned int i = 0; i < fine_indices.size(); ++i)
                {
                  const auto [component, k] = fine_fe.system_to_component_index(i);
                  const auto g              = fine_indices[i];
                  if (!fine_partitioner.in_local_range(g) || fine_constraints.is_constrained(g))
                    continue;
                  const unsigned int local = fine_partitioner.global_to_local(g);
                  if (!written[local])
                    fine[first_fine + component * n_fine + fine_lexicographic[k]] = local, written[local] = true;
                }
              for (unsigned int i = 0; i < coarse_indices.size(); ++i)
                {
                  const auto [component, k] = coarse_fe.system_to_component_index(i);
                  const auto g              = coarse_indices[i];
                  if (!coarse_partitioner.in_local_range(g) && !coarse_partitioner.is_ghost_entry(g))
                    return false;
                  if (!coarse_constraints.is_constrained(g))
                    coarse[first_coarse + component * n_coarse + coarse_lexicographic[k]] =
                      coarse_partitioner.global_to_local(g);
                }
            }
          ++coarse_cell;
        }
      // Every owned, free fine DoF must have a writer among this rank's cells.
      for (unsigned int local = 0; local < written.size(); ++local)
        if (!written[local] && !fine_constraints.is_constrained(fine_partitioner.local_to_global(local)))
          return false;
      return coarse_cell == coarse_dofs.end();
    }

    void prolongate_and_add(VectorType &dst, const VectorType &src) const
    {
      coarse_ghosted.copy_locally_owned_data_from(src);
      coarse_ghosted.update_ghost_values();
      std::vector<double> values(n_coarse), result(n_fine);
      const std::size_t   n_cells = coarse.size() / (dim * n_coarse);
      for (std::size_t c = 0; c < n_cells; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int *from = &coarse[(c * dim + d) * n_coarse];
            const unsigned int *to   = &fine[(c * dim + d) * n_fine];
            for (unsigned int j = 0; j < n_coarse; ++j)
              values[j] = from[j] == skip ? 0. : coarse_ghosted.local_element(from[j]);
            apply_tensor(false, values.data(), result.data());
            for (unsigned int i = 0; i < n_fine; ++i)
              if (to[i] != skip)
                dst.local_element(to[i]) += result[i];
          }
      coarse_ghosted.zero_out_ghost_values();
    }

    void restrict_and_add(VectorType &dst, const VectorType &src) const
    {
      coarse_ghosted = 0.;
      coarse_ghosted.zero_out_ghost_values();
      std::vector<double> values(n_fine), sums(n_coarse);
      const std::size_t   n_cells = coarse.size() / (dim * n_coarse);
      for (std::size_t c = 0; c < n_cells; ++c)
        for (unsigned int d = 0; d < dim; ++d)
          {
            const unsigned int *to   = &coarse[(c * dim + d) * n_coarse];
            const unsigned int *from = &fine[(c * dim + d) * n_fine];
            for (unsigned int i = 0; i < n_fine; ++i)
              values[i] = from[i] == skip ? 0. : src.local_element(from[i]);
            apply_tensor(true, values.data(), sums.data());
            for (unsigned int j = 0; j < n_coarse; ++j)
              if (to[j] != skip)
                coarse_ghosted.local_element(to[j]) += sums[j];
          }
      coarse_ghosted.compress(VectorOperation::add);
      dst += coarse_ghosted;
    }
  };

  template <int dim>
  LevelTransfer<dim>::LevelTransfer(const MGLevelObject<const DoFHandler<dim> *>    &dofs,
                                    const MGLevelObject<AffineConstraints<double>> &constraints,
                                    const InitializeVector &initialize_in, const bool own_transfer)
    : own(dofs.min_level(), dofs.max_level())
    , dealii_transfers(dofs.min_level(), dofs.max_level())
    , initialize(initialize_in)
  {
    const MPI_Comm communicator = dofs[dofs.max_level()]->get_communicator();
    for (unsigned int level = dofs.min_level() + 1; level <= dofs.max_level(); ++level)
      {
        // Every rank must take the same way (the transfers communicate).
        bool cell_wise = own_transfer && only_held_at_zero(constraints[level]) &&
                         only_held_at_zero(constraints[level - 1]);
        if (Utilities::MPI::min(cell_wise ? 1 : 0, communicator) == 1)
          {
            VectorType fine_layout, coarse_layout;
            initialize(level, fine_layout);
            initialize(level - 1, coarse_layout);
            auto transfer = std::make_unique<CellWise>();
            cell_wise     = transfer->reinit(*dofs[level], *dofs[level - 1], constraints[level],
                                         constraints[level - 1], fine_layout, coarse_layout);
            if (Utilities::MPI::min(cell_wise ? 1 : 0, communicator) == 1)
              {
                own[level] = std::move(transfer);
                continue;
              }
          }
        dealii_transfers[level].reinit_polynomial_transfer(*dofs[level], *dofs[level - 1], constraints[level],
                                                           constraints[level - 1]);
      }
  }

  template <int dim>
  LevelTransfer<dim>::~LevelTransfer() = default;

  template <int dim>
  void LevelTransfer<dim>::prolongate(const unsigned int to_level, VectorType &dst, const VectorType &src) const
  {
    dst = 0.;
    prolongate_and_add(to_level, dst, src);
  }

  template <int dim>
  void LevelTransfer<dim>::prolongate_and_add(const unsigned int to_level, VectorType &dst,
                                              const VectorType &src) const
  {
    if (own[to_level])
      own[to_level]->prolongate_and_add(dst, src);
    else
      dealii_transfers[to_level].prolongate_and_add(dst, src);
  }

  template <int dim>
  void LevelTransfer<dim>::restrict_and_add(const unsigned int from_level, VectorType &dst,
                                            const VectorType &src) const
  {
    if (own[from_level])
      own[from_level]->restrict_and_add(dst, src);
    else
      dealii_transfers[from_level].restrict_and_add(dst, src);
  }

  template <int dim>
  unsigned int LevelTransfer<dim>::n_own_levels() const
  {
    unsigned int n = 0;
    for (unsigned int level = own.min_level(); level <= own.max_level(); ++level)
      n += own[level] ? 1 : 0;
    return n;
  }

  template class LevelTransfer<2>;
  template class LevelTransfer<3>;
} // namespace compliant::fast_solver
