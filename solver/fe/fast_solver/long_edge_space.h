// The coarse space of the p-multigrid on long cells: continuous functions quadratic along the
// long edges of each cell and linear across them (on a cell long in x, Q(2,1,1); a plate cell
// long in x and y, Q(2,2,1)), as a subspace of the degree-2 space on the same mesh. It holds the
// bending modes that the degree-1 space locks on (a beam's curvature along a 12 : 1 cell), which
// neither Q1 nor a smoother on the diagonal can reach.
//
// Its degrees of freedom are the degree-2 ones at the vertices and at the midpoints of long
// edges (an edge is long where a cell it bounds is long in its direction, long_cells: at least
// some times longer in it than in its shortest direction, in a thin part, fast_solver/long_cells.h). Every other degree-2 node takes the Boolean-sum
// (Coons) blend of the nodes of its edge, face or cell: exact on the functions linear in one
// direction, and defined by the face alone, so the space is conforming. DoFs held at zero by
// the constraints are not in the space.
#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include "fast_solver/long_cells.h"

#include <petscmat.h>

#include <cstdint>
#include <vector>

namespace compliant::fast_solver
{
  struct LongEdgeSpace
  {
    Mat                             prolongation = nullptr; // degree-2 DoFs x coarse DoFs (owned rows, PETSc AIJ)
    dealii::types::global_dof_index n_coarse     = 0;       // global
    dealii::types::global_dof_index n_free_nodes = 0;       // global count of free midpoint nodes
    dealii::types::global_dof_index n_owned_coarse = 0;
    // The degree-2 DoF of each owned coarse DoF, in coarse order (a coarse DoF is a degree-2 DoF).
    std::vector<dealii::types::global_dof_index> owned_coarse_dofs;

    // The prolongation cell by cell, for the Galerkin matrix from a cell kernel: on a locally
    // owned cell, the coarse DoFs its functions reach and, per nonzero, the cell's degree-2 DoF
    // (in the FESystem's numbering), the slot of the coarse DoF and the weight (a power of 1/2).
    struct Entry
    {
      std::uint8_t dof, slot;
      float        weight;
    };
    struct Cell
    {
      std::vector<PetscInt>      columns;
      std::vector<Entry>         entries;    // by slot: those of slot k from slot_begin[k]
      std::vector<std::uint16_t> slot_begin; // columns.size() + 1 offsets
    };
    std::vector<Cell>         cells;
    // The coarse DoFs of each other rank's cell at an owned DoF: the Galerkin matrix's rows of
    // this rank get their entries from those cells too.
    std::vector<std::vector<PetscInt>> neighbour_columns;
    std::vector<unsigned int> cell_of_active_index; // numbers::invalid_unsigned_int where not owned

    LongEdgeSpace() = default;
    LongEdgeSpace(const LongEdgeSpace &) = delete;
    LongEdgeSpace &operator=(const LongEdgeSpace &) = delete;
    ~LongEdgeSpace();
  };

  // dofs: a degree-2 FESystem of dim FE_Q(2); constraints: homogeneous, no entries (no hanging
  // nodes or ties), with the locally relevant lines.
  template <int dim>
  void build_long_edge_space(const dealii::DoFHandler<dim> &dofs, const dealii::AffineConstraints<double> &constraints,
                             const LongCells &long_cells, LongEdgeSpace &space);
} // namespace compliant::fast_solver
