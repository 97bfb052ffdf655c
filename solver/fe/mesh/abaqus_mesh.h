// Meshes in the Abaqus/CalculiX input format (.inp): nodes, elements, element sets (*ELSET, and
// ELSET= on *ELEMENT), node sets (*NSET, NSET= on *NODE) and element-face surfaces (*SURFACE),
// turned into the Gmsh 2.2 text and physical names of MeshedGeometry, so that the set names
// are the case file's vocabulary. Free of deal.II.
//
// Body cells: the elements of the highest dimension (C3D4/C3D10, C3D8/C3D20 and their R/I/H
// variants; CPS/CPE/CAX/S/M3D triangles and quadrilaterals of 3, 4, 6 or 8 nodes in 2D); second-order
// elements give their corner nodes (the solver chooses its own degree). Each body cell belongs to
// one body group: the element set of its *SOLID SECTION, else the smallest *ELSET holding it that
// no *SURFACE names, else any other set holding it (an *ELEMENT line's ELSET= last). Boundary groups: lower-dimensional elements in an element set (what gmsh writes), the
// element faces of a *SURFACE, and the boundary faces whose corners all lie in a node set; a face
// in several groups goes to the smallest. Everything after the mesh (*MATERIAL, *STEP, ...) is
// skipped.
#pragma once

#include "mesh/gmsh_geometry.h"

#include <string>

namespace compliant
{
  // Throws std::runtime_error naming the file and line on anything it cannot read.
  MeshedGeometry read_abaqus_mesh(const std::string &file);
} // namespace compliant
