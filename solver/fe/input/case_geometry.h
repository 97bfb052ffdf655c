// The mesh of a case's geometry: meshed by gmsh on rank 0 and shared with every rank, so all
// ranks see the same mesh text or the same error.
#pragma once

#include <mpi.h>

#include "input/case_file.h"
#include "mesh/gmsh_geometry.h"

namespace compliant
{
  // Meshes Geometry/Mesh file with the case's parameters (curved boundaries dropped when the case
  // turns them off) and prints the curved shapes found. Throws InputError naming the case file.
  MeshedGeometry mesh_case_geometry(const CaseParameters &parameters, MPI_Comm communicator);
} // namespace compliant
