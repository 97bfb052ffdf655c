// The Galerkin matrix P^T K P of a subspace of the degree-2 space (the long-edge space), computed
// from a matrix-free cell kernel: the kernel runs on the cell's share of each coarse basis function
// (its columns of P) instead of on every unit vector, and P^T is applied to the result on the cell.
// Included by the operators' implementation files; `local` runs evaluate, the quadrature-point
// operation and integrate on an FEEvaluation.
#pragma once

#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/matrix_free.h>

#include "fast_solver/long_edge_space.h"
#include "linear_algebra/petsc_check.h"

#include <petscmat.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace compliant::fast_solver
{
  template <int dim, int degree, int n_q, typename Number, typename LocalFunction>
  void add_subspace_matrix(const dealii::MatrixFree<dim, Number, SimdArray<Number>> &data, const unsigned int quad,
                           const LongEdgeSpace &space, Mat matrix, const LocalFunction &local)
  {
    dealii::FEEvaluation<dim, degree, n_q, dim, Number, SimdArray<Number>> phi(data, 0, quad);
    const auto        &lexicographic = data.get_shape_info(0, quad).lexicographic_numbering;
    const unsigned int n             = phi.dofs_per_cell;
    std::vector<unsigned int> position(n); // FEEvaluation's place of each FESystem DoF
    for (unsigned int i = 0; i < n; ++i)
      position[lexicographic[i]] = i;
    constexpr unsigned int lanes = SimdArray<Number>::size();
    std::vector<double>    block;
    for (unsigned int batch = 0; batch < data.n_cell_batches(); ++batch)
      {
        phi.reinit(batch);
        const unsigned int                 filled = data.n_active_entries_per_cell_batch(batch);
        std::array<const LongEdgeSpace::Cell *, lanes> cells{};
        std::size_t                        n_columns = 0;
        for (unsigned int lane = 0; lane < filled; ++lane)
          {
            const unsigned int index =
              space.cell_of_active_index[data.get_cell_iterator(batch, lane)->active_cell_index()];
            if (index == dealii::numbers::invalid_unsigned_int)
              throw std::logic_error("long-edge space: a cell of the operator is not in the space");
            cells[lane] = &space.cells[index];
            n_columns   = std::max(n_columns, cells[lane]->columns.size());
          }
        block.assign(filled * n_columns * n_columns, 0.);
        for (std::size_t j = 0; j < n_columns; ++j)
          {
            for (unsigned int i = 0; i < n; ++i)
              phi.begin_dof_values()[i] = Number(0);
            for (unsigned int lane = 0; lane < filled; ++lane)
              if (j < cells[lane]->columns.size())
                for (unsigned int k = cells[lane]->slot_begin[j]; k < cells[lane]->slot_begin[j + 1]; ++k)
                  {
                    const auto &e = cells[lane]->entries[k];
                    phi.begin_dof_values()[position[e.dof]][lane] += e.weight;
                  }
            local(phi);
            // Row k of column j: sum over the cell's DoFs of P(dof, k) (K P_j)(dof).
            for (unsigned int lane = 0; lane < filled; ++lane)
              for (const auto &e : cells[lane]->entries)
                block[(lane * n_columns + e.slot) * n_columns + j] +=
                  e.weight * phi.begin_dof_values()[position[e.dof]][lane];
          }
        for (unsigned int lane = 0; lane < filled; ++lane)
          {
            const auto     &columns = cells[lane]->columns;
            const PetscInt  m       = columns.size();
            // Rows past this cell's own columns are zero padding: copy the m x m block out.
            std::vector<PetscScalar> values(m * m);
            for (PetscInt r = 0; r < m; ++r)
              for (PetscInt c = 0; c < m; ++c)
                values[r * m + c] = block[(lane * n_columns + r) * n_columns + c];
            PetscErrorCheck("long-edge Galerkin matrix")(
              MatSetValues(matrix, m, columns.data(), m, columns.data(), values.data(), ADD_VALUES), "MatSetValues");
          }
      }
  }
} // namespace compliant::fast_solver
