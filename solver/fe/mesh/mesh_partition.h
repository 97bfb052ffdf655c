// How the mesh is spread over the MPI ranks. 'shared': every rank holds the whole mesh and owns a
// METIS part of it (what constraints between arbitrary DoFs, refine flags over the whole mesh and
// gathered constraints need). 'distributed': each rank holds only its METIS part plus one layer of
// ghost cells (parallel::fullydistributed), so the memory per rank falls as ranks are added.
#pragma once

#include <deal.II/distributed/tria_base.h>

#include "mesh/partition_request.h"

#include <memory>
#include <string>

namespace compliant
{
  enum class MeshPartition
  {
    shared,
    distributed
  };

  struct MeshPartitionChoice
  {
    MeshPartition partition = MeshPartition::shared;
    std::string   note; // why, for the log ("" when nothing to say)
  };

  // From 'Discretization/Mesh partition'. 'auto' distributes from
  // auto_distributed_dofs estimated DoFs on more than one rank. whole_mesh_reason is non-empty
  // when the analysis needs the whole mesh on every rank (says what for): then 'distributed' is
  // refused (std::invalid_argument) and 'auto' shares.
  MeshPartitionChoice choose_mesh_partition(PartitionRequest requested, double estimated_dofs,
                                            unsigned int n_ranks,
                                            const std::string &whole_mesh_reason);
  constexpr double auto_distributed_dofs = 2e5;

  // DoFs of a vector-valued Lagrange element of the given degree on cells of a mesh refined
  // globally (a rough estimate: one node per cell per degree^dim).
  double estimate_dofs(std::size_t coarse_cells, unsigned int dim, unsigned int global_refinements,
                       unsigned int degree);

  template <int dim>
  std::unique_ptr<dealii::parallel::TriangulationBase<dim>>
  make_triangulation(MeshPartition partition, MPI_Comm communicator);

  inline std::string to_string(const MeshPartition partition)
  {
    return partition == MeshPartition::shared ? "shared" : "distributed";
  }
} // namespace compliant
