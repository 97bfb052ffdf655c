#include "mesh/mesh_partition.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/shared_tria.h>

#include <cmath>
#include <stdexcept>

namespace compliant
{
  double estimate_dofs(const std::size_t coarse_cells, const unsigned int dim,
                       const unsigned int global_refinements, const unsigned int degree)
  {
    const double cells = static_cast<double>(coarse_cells) * std::pow(2.0, dim * global_refinements);
    return dim * cells * std::pow(static_cast<double>(degree), dim);
  }

  PartitionRequest partition_request_from_string(const std::string &text)
  {
    if (text == "auto")
      return PartitionRequest::automatic;
    if (text == "shared")
      return PartitionRequest::shared;
    if (text == "distributed")
      return PartitionRequest::distributed;
    throw std::invalid_argument("Discretization/Mesh partition: expected auto, shared or "
                                "distributed, got '" + text + "'");
  }

  MeshPartitionChoice choose_mesh_partition(const PartitionRequest requested, const double estimated_dofs,
                                            const unsigned int n_ranks,
                                            const std::string &whole_mesh_reason)
  {
    if (requested == PartitionRequest::shared)
      return {MeshPartition::shared, ""};
    if (requested == PartitionRequest::distributed)
      {
        if (!whole_mesh_reason.empty())
          throw std::invalid_argument("Discretization/Mesh partition = distributed is not possible: " +
                                      whole_mesh_reason +
                                      " needs the whole mesh on every rank; use shared or auto");
        if (n_ranks == 1)
          return {MeshPartition::shared, "one rank holds the whole mesh anyway"};
        return {MeshPartition::distributed, ""};
      }
    if (n_ranks > 1 && estimated_dofs >= auto_distributed_dofs)
      {
        if (!whole_mesh_reason.empty())
          return {MeshPartition::shared, "auto: shared, since " + whole_mesh_reason +
                                           " needs the whole mesh on every rank"};
        return {MeshPartition::distributed, "auto: distributed (each rank holds its part of a "
                                            "large mesh)"};
      }
    return {MeshPartition::shared, ""};
  }

  template <int dim>
  std::unique_ptr<dealii::parallel::TriangulationBase<dim>>
  make_triangulation(const MeshPartition partition, MPI_Comm communicator)
  {
    if (partition == MeshPartition::distributed)
      return std::make_unique<dealii::parallel::fullydistributed::Triangulation<dim>>(communicator);
    return std::make_unique<dealii::parallel::shared::Triangulation<dim>>(
      communicator, dealii::Triangulation<dim>::none, false,
      dealii::parallel::shared::Triangulation<dim>::partition_metis);
  }

  template std::unique_ptr<dealii::parallel::TriangulationBase<2>> make_triangulation<2>(MeshPartition, MPI_Comm);
  template std::unique_ptr<dealii::parallel::TriangulationBase<3>> make_triangulation<3>(MeshPartition, MPI_Comm);
} // namespace compliant
