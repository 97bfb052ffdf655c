// Boundary groups that reach inside the body: deal.II cannot give a face between two cells a
// boundary id (it stops with a stack trace), so such a group is refused with the group named.
// Uses the gmsh model of the open session (mesh/gmsh_geometry.cc).
#pragma once

#include "mesh/gmsh_geometry.h"

#include <string>

namespace compliant
{
  // Throws std::runtime_error naming `file` and the group: a boundary group's entity between two
  // meshed regions of the body (from gmsh's topology, a glued .geo), or an element face of the
  // group shared by two cells of the body (from the mesh itself: a .msh file carries no topology).
  void refuse_interior_boundaries(const std::string &file, const MeshedGeometry &result);
} // namespace compliant
