#include "mesh/mesh_reader.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/fully_distributed_tria.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria_description.h>

#include "mesh/curved_manifolds.h"
#include "mesh/memory_estimate.h"

#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace
  {
    // Curved faces on the coarse mesh as read, before any refinement puts vertices on them.
    template <int dim>
    void curve_boundaries(dealii::Triangulation<dim> &triangulation, const MeshedGeometry &geometry,
                          const unsigned int element_degree)
    {
      if (geometry.curved.exact.empty())
        return;
      mark_curved_faces(triangulation, geometry.curved.exact);
      attach_curved_manifolds(triangulation, geometry.curved.exact);
      const unsigned int n_straight = straighten_folding_faces(triangulation, element_degree);
      if (n_straight > 0 && dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
        std::cout << "Curved boundaries: " << n_straight
                  << " faces kept straight: following the arc would fold their thin cells "
                     "(a finer gmsh mesh there curves them)\n";
    }

    // Rank 0 reads and refines the whole mesh, METIS cuts it, and each rank receives only its
    // part with one layer of ghost cells; the serial mesh is gone before the solve.
    template <int dim>
    void create_fully_distributed(dealii::parallel::fullydistributed::Triangulation<dim> &triangulation,
                                  const MeshedGeometry &geometry, const unsigned int global_refinements,
                                  const std::vector<std::vector<bool>> &adaptive_refinements,
                                  const unsigned int element_degree)
    {
      if (!adaptive_refinements.empty())
        throw std::logic_error("create_triangulation: refine flags over the whole mesh need a "
                               "shared triangulation");
      // Checked on every rank before rank 0 starts, so that all ranks stop together.
      refuse_refinement_beyond_memory(geometry.n_cells, dim, global_refinements, element_degree, 1);
      const MPI_Comm communicator = triangulation.get_communicator();
      const auto     description =
        dealii::TriangulationDescription::Utilities::create_description_from_triangulation_in_groups<dim, dim>(
          [&](dealii::Triangulation<dim> &serial) {
            dealii::GridIn<dim> grid_in;
            grid_in.attach_triangulation(serial);
            std::istringstream in(geometry.msh_text);
            grid_in.read_msh(in);
            curve_boundaries(serial, geometry, element_degree);
            serial.refine_global(global_refinements);
          },
          [](dealii::Triangulation<dim> &serial, const MPI_Comm &comm, const unsigned int) {
            dealii::GridTools::partition_triangulation(dealii::Utilities::MPI::n_mpi_processes(comm),
                                                       serial);
          },
          communicator, dealii::Utilities::MPI::n_mpi_processes(communicator));
      // The manifolds go on first: building the levels of the description refines the coarse
      // cells, and new vertices on curved faces must land on the curve, not on the chord.
      attach_curved_manifolds(triangulation, geometry.curved.exact);
      triangulation.create_triangulation(description);
    }
  } // namespace

  template <int dim>
  void create_triangulation(dealii::Triangulation<dim> &triangulation,
                            const MeshedGeometry &geometry, const unsigned int global_refinements,
                            const std::vector<std::vector<bool>> &adaptive_refinements,
                            const unsigned int element_degree)
  {
    if (auto *distributed =
          dynamic_cast<dealii::parallel::fullydistributed::Triangulation<dim> *>(&triangulation))
      return create_fully_distributed(*distributed, geometry, global_refinements,
                                      adaptive_refinements, element_degree);
    dealii::GridIn<dim> grid_in;
    grid_in.attach_triangulation(triangulation);
    std::istringstream in(geometry.msh_text);
    grid_in.read_msh(in);
    curve_boundaries(triangulation, geometry, element_degree);
    const auto *parallel =
      dynamic_cast<const dealii::parallel::TriangulationBase<dim> *>(&triangulation);
    refuse_refinement_beyond_memory(triangulation.n_active_cells(), dim, global_refinements, element_degree,
                                    parallel ? dealii::Utilities::MPI::n_mpi_processes(parallel->get_communicator()) : 1);
    triangulation.refine_global(global_refinements);
    for (const auto &flags : adaptive_refinements)
      {
        if (!triangulation.all_reference_cells_are_hyper_cube())
          throw std::invalid_argument("adaptive refinement needs quadrilaterals or hexahedra "
                                      "(deal.II has no hanging nodes on triangles and tetrahedra)");
        // save_refine_flags keeps dim bits per active cell (the refinement case).
        if (flags.size() != dim * triangulation.n_active_cells())
          throw std::logic_error("create_triangulation: " + std::to_string(flags.size()) +
                                 " refine flags do not match a mesh of " +
                                 std::to_string(triangulation.n_active_cells()) + " cells");
        triangulation.load_refine_flags(flags);
        triangulation.execute_coarsening_and_refinement();
      }
  }

  template void create_triangulation<2>(dealii::Triangulation<2> &, const MeshedGeometry &, unsigned int,
                                       const std::vector<std::vector<bool>> &, unsigned int);
  template void create_triangulation<3>(dealii::Triangulation<3> &, const MeshedGeometry &, unsigned int,
                                       const std::vector<std::vector<bool>> &, unsigned int);
} // namespace compliant
