// The curved boundary entities of the gmsh geometry, found from the geometry itself (its
// parametrization sampled, not the mesh), so that the solver can place refined vertices and
// high-order mapping points on the true surface: circles (2D), cylinders and spheres (3D) by their
// closed forms, any other curve (2D) or surface (3D) by samples of its parametrization. Free of
// deal.II.
#pragma once

#include "mesh/sampled_geometry.h"

#include <string>
#include <vector>

namespace compliant
{
  struct CurvedBoundary
  {
    enum Shape
    {
      circle   = 0, // a 2D curve: centre, radius
      cylinder = 1, // a 3D surface: a point on the axis (centre), axis, radius
      sphere   = 2, // a 3D surface: centre, radius
      sampled_curve   = 3, // any other 2D curve: samples of its parametrization
      sampled_surface = 4  // any other 3D surface: samples of its parametrization
    };
    int                 shape  = circle;
    int                 entity = 0; // gmsh tag of the curve or surface
    double              centre[3] = {0, 0, 0};
    double              axis[3]   = {0, 0, 1};
    double              radius    = 0;
    ParametricSamples   samples; // sampled_curve and sampled_surface only
    std::vector<double> face_centres; // x,y,z of the vertex centre of each mesh face on it

    template <class Archive>
    void serialize(Archive &archive, const unsigned int)
    {
      archive &shape &entity &centre &axis &radius &samples &face_centres;
    }
  };

  struct CurvedEntities
  {
    std::vector<CurvedBoundary> exact;        // every curved entity followed
    std::vector<std::string>    straightened; // the ones that cannot be, and why, e.g.
                                              // "curve 7 (BSpline): gmsh cannot evaluate it"

    template <class Archive>
    void serialize(Archive &archive, const unsigned int)
    {
      archive &exact &straightened;
    }
  };

  // For the model gmsh has open and meshed: every entity of dimension dimension-1 that carries
  // mesh faces and is not straight/planar. Entities without a parametrization (a .msh file's
  // discrete entities) are not looked at.
  CurvedEntities find_curved_entities(int dimension);

  // The degree of the geometry mapping: the element's where a boundary is curved (isoparametric),
  // else 1 (straight cells cost less to map).
  inline unsigned int mapping_degree(const CurvedEntities &curved, const unsigned int element_degree)
  {
    return curved.exact.empty() ? 1 : element_degree;
  }
} // namespace compliant
