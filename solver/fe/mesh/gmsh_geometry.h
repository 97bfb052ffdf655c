// Geometry through the gmsh API: parametric .geo files (ONELAB "Parameters/..." constants) or
// ready .msh files, meshed on one rank and handed over as Gmsh 2.2 text. Physical group names
// are the vocabulary of case files; this is where they are read.
#pragma once

#include "mesh/curved_entities.h"

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
  };

  // The ONELAB parameters a .geo file declares with DefineConstant[... Name "Parameters/x" ...].
  // A .msh file has none. Throws std::runtime_error naming the file if gmsh cannot read it.
  std::vector<GeometryParameter> read_geometry_parameters(const std::string &file);

  struct MeshedGeometry
  {
    int                        dimension = 0;
    std::string                msh_text; // Gmsh 2.2 ASCII, physical elements only
    std::map<std::string, int> boundary_ids; // physical groups of dimension-1
    std::map<std::string, int> material_ids; // physical groups of full dimension
    std::size_t                n_cells = 0;
    CurvedEntities             curved; // the curved boundaries (followed or not)
  };

  // Sets the given parameters, meshes a .geo (or loads a .msh) and returns the mesh text with
  // its physical names. Throws std::runtime_error with the file name on any failure.
  MeshedGeometry mesh_geometry(const std::string &file,
                               const std::map<std::string, double> &parameters);
} // namespace compliant
