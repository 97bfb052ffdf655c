// Geometry through the gmsh API: parametric .geo files (ONELAB "Parameters/..." constants) or
// ready .msh files, meshed on one rank and handed over as Gmsh 2.2 text. Physical group names
// are the vocabulary of case files; this is where they are read. gmsh runs in a child process
// (mesh/contained_call.h) under a memory cap and a time limit, and a mesh estimated to exceed the
// memory of the run is refused before it is built (mesh/mesh_size_guard.h): a crash, a hang or a
// runaway mesh in gmsh ends as one error naming the file and its parameters.
#pragma once

#include "mesh/curved_entities.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct GeometryParameter
  {
    std::string name;  // without the "Parameters/" prefix
    double      value; // default from the .geo file
    std::string help;

    template <class Archive>
    void serialize(Archive &archive, const unsigned int)
    {
      archive &name &value &help;
    }
  };

  // The ONELAB parameters a .geo file declares with DefineConstant[... Name "Parameters/x" ...].
  // A .msh file has none. Throws std::runtime_error naming the file if gmsh cannot read it, or
  // fails to within `seconds` (0: the automatic limit, 60 s).
  std::vector<GeometryParameter> read_geometry_parameters(const std::string &file, double seconds = 0);

  struct MeshedGeometry
  {
    int                        dimension = 0;
    std::string                msh_text; // Gmsh 2.2 ASCII, physical elements only
    std::map<std::string, int> boundary_ids; // physical groups of dimension-1
    std::map<std::string, int> material_ids; // physical groups of full dimension
    std::size_t                n_cells = 0;
    CurvedEntities             curved; // the curved boundaries (followed or not)

    template <class Archive>
    void serialize(Archive &archive, const unsigned int)
    {
      archive &dimension &msh_text &boundary_ids &material_ids &n_cells &curved;
    }
  };

  struct MeshingLimits
  {
    // Geometry/Maximum cells; 0: automatic, what the memory available holds at ~1 kB per cell on
    // each of `ranks` ranks (each holds the whole mesh at some point).
    std::uint64_t maximum_cells = 0;
    unsigned int  ranks         = 1;
    // Geometry/Meshing time limit in seconds; 0: automatic, 60 s to read the geometry and mesh
    // its curves, then 60 s + 100 us per estimated cell.
    double seconds = 0;
  };

  // Sets the given parameters, meshes a .geo (or loads a .msh) and returns the mesh text with
  // its physical names. Throws std::runtime_error with the file name and the parameters on any
  // failure: gmsh's error, a crash, a time-out, or a mesh estimated beyond limits.maximum_cells.
  MeshedGeometry mesh_geometry(const std::string &file,
                               const std::map<std::string, double> &parameters,
                               const MeshingLimits &limits = {});
} // namespace compliant
