// How many cells gmsh is about to make, estimated before it makes them, so that a geometry
// parameter off by a unit (t = 1e-6 in a millimetre case asks for ~1e8 cells) is refused in a
// second instead of exhausting the machine. For the model gmsh has open, in three steps that each
// cost far less than the next meshing stage:
//  1. before any meshing, from the transfinite constraints alone (the curves' point counts);
//  2. after the curves are meshed, per surface: a transfinite one exactly (the product of two
//     adjacent sides' segment counts), any other as A / h^2 with A the area its boundary segments
//     enclose and h their mean length, times 2.31 for triangles (an equilateral triangle covers
//     0.433 h^2) or 1.15 where recombined into quadrilaterals. In 3D the volumes get at least half
//     their boundary's faces;
//  3. in 3D, after the surfaces are meshed, per volume: a transfinite hexahedral block exactly,
//     any other as V / h^3 with V the volume its surface mesh encloses and h its mean edge length,
//     times 8.5 for tetrahedra (a regular one holds 0.118 h^3), 1 where every face is a
//     quadrilateral (extruded, recombined blocks).
// Size fields that make the interior much finer than the boundary are not seen: the memory cap of
// the contained meshing (gmsh_geometry.cc) stops those. Uses gmsh; free of deal.II.
#pragma once

#include <map>
#include <set>
#include <string>

namespace compliant
{
  struct MeshConstraints
  {
    std::map<int, double> transfinite_curves; // curve tag -> segments
    std::set<int>         transfinite_surfaces, transfinite_volumes, recombined_surfaces;
    bool                  recombine_all = false;
  };

  // The transfinite and recombination constraints of the model gmsh has open (built-in kernel
  // entities, read back through a .geo_unrolled export: gmsh 4.8 has no getter for them).
  MeshConstraints read_mesh_constraints();

  struct CellEstimate
  {
    double      cells = 0;
    std::string basis; // "the transfinite curves", "the curve meshes", "the surface meshes"
  };

  // Step 1: cells of the structured blocks whose counts the constraints fix (0 if none).
  CellEstimate estimate_cells_before_meshing(int dimension, const MeshConstraints &constraints);

  // Step 2: needs the curves meshed (gmsh::model::mesh::generate(1)).
  CellEstimate estimate_cells_from_curves(int dimension, const MeshConstraints &constraints);

  // Step 3 (3D): needs the surfaces meshed (gmsh::model::mesh::generate(2)).
  CellEstimate estimate_cells_from_surfaces(const MeshConstraints &constraints);
} // namespace compliant
