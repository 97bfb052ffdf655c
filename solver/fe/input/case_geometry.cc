#include "input/case_geometry.h"

#include <deal.II/base/mpi.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <iostream>

namespace compliant
{
  namespace
  {
    void report_curved_boundaries(const CurvedEntities &curved)
    {
      if (!curved.exact.empty())
        {
          // In the order of CurvedBoundary::Shape; the last two followed through their samples.
          const char  *names[]   = {"circle", "cylinder", "sphere", "other curve", "other surface"};
          unsigned int counts[5] = {0, 0, 0, 0, 0};
          for (const auto &boundary : curved.exact)
            ++counts[boundary.shape];
          std::cout << "Curved boundaries:";
          for (unsigned int s = 0; s < 5; ++s)
            if (counts[s] > 0)
              std::cout << " " << counts[s] << " " << names[s] << (counts[s] > 1 ? "s" : "")
                        << (s >= CurvedBoundary::sampled_curve ? " (sampled)" : "");
          std::cout << " follow the geometry; cells mapped at the element degree\n";
        }
      for (const auto &entity : curved.straightened)
        std::cout << "Curved boundaries: " << entity
                  << ": its faces stay straight\n";
    }
  } // namespace

  // Meshing happens on rank 0; every rank gets the same mesh text, or the same error.
  MeshedGeometry mesh_case_geometry(const CaseParameters &p, MPI_Comm comm)
  {
    MeshedGeometry geometry;
    std::string    error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          MeshingLimits limits;
          limits.maximum_cells = p.maximum_cells;
          limits.ranks         = dealii::Utilities::MPI::n_mpi_processes(comm);
          limits.seconds       = p.meshing_time_limit;
          geometry             = mesh_geometry(p.mesh_file, p.geometry_parameters, limits);
          if (!p.curved_boundaries)
            geometry.curved = {};
          report_curved_boundaries(geometry.curved);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError("case file '" + p.case_file + "', Geometry/Mesh file: " + error);
    geometry.msh_text     = dealii::Utilities::MPI::broadcast(comm, geometry.msh_text, 0);
    geometry.dimension    = dealii::Utilities::MPI::broadcast(comm, geometry.dimension, 0);
    geometry.boundary_ids = dealii::Utilities::MPI::broadcast(comm, geometry.boundary_ids, 0);
    geometry.material_ids = dealii::Utilities::MPI::broadcast(comm, geometry.material_ids, 0);
    geometry.n_cells      = dealii::Utilities::MPI::broadcast(comm, geometry.n_cells, 0);
    geometry.curved       = dealii::Utilities::MPI::broadcast(comm, geometry.curved, 0);
    return geometry;
  }
} // namespace compliant
