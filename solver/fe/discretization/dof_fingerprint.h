// Whether two DoFHandlers of one element on twin meshes (built the same way) number their DoFs
// alike, so that a vector or a solver of one serves the other: the p-multigrid's lower solver, the
// goal-oriented ladder's linear twin of a finite-strain model.
#pragma once

#include <deal.II/dofs/dof_handler.h>

#include <mpi.h>

#include <vector>

namespace compliant
{
  // Sums over the locally owned cells of (index + 1) (i + 1) times each coordinate of the cell's
  // centre, for the cell's i-th DoF, over all ranks, and the DoF count: equal on two DoFHandlers
  // exactly when they number the DoFs alike (up to a coincidence of sums).
  template <int dim>
  std::vector<double> cell_dof_fingerprint(const dealii::DoFHandler<dim> &dofs, MPI_Comm communicator);

  // The fingerprints equal and, on every rank, the same owned DoFs.
  template <int dim>
  bool numbered_alike(const dealii::DoFHandler<dim> &a, const dealii::DoFHandler<dim> &b, MPI_Comm communicator);
} // namespace compliant
