// Curved boundaries that are no circles, followed through samples of gmsh's parametrization
// (issue 28, item 5): on meshes/spline_profile_2d.geo (a BSpline notch, a Catmull-Rom Spline
// bottom) refined twice, every vertex and every support point of the mapping (degree 3, the
// element's) on those curves lies on gmsh's curve to 1e-8 of the bar's length, where the chords'
// midpoints miss it by about 1e-5 of it; the elliptical hole's Ellipse arcs are followed, not
// straightened; and in 3D the hole's faces (extruded ellipse arcs: gmsh surfaces sampled on a
// grid) hold every refined vertex and mapping point on x^2/4 + y^2 = 1.
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/tria.h>

#include "mesh/gmsh_geometry.h"
#include "mesh/mesh_reader.h"

#include <gmsh.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

using namespace compliant;

namespace
{
  const std::string meshes = std::string(COMPLIANT_SOURCE_DIR) + "/meshes/";

  // Cell-unit coordinates of the points at `unit` (0..1) along face f of a quadrilateral.
  dealii::Point<2> on_face(const unsigned int f, const double unit)
  {
    return f < 2 ? dealii::Point<2>(f, unit) : dealii::Point<2>(unit, f - 2);
  }

  // The largest distance from the points to the closest of gmsh's curves `tags` of the .geo.
  double distance_to_curves(const std::string &file, const std::vector<int> &tags, const std::vector<double> &xyz)
  {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::open(file);
    std::vector<double> nearest(xyz.size() / 3, 1e300);
    for (const int tag : tags)
      {
        std::vector<double> closest, parameters;
        gmsh::model::getClosestPoint(1, tag, xyz, closest, parameters);
        for (std::size_t k = 0; k < nearest.size(); ++k)
          nearest[k] = std::min(nearest[k], std::hypot(xyz[3 * k] - closest[3 * k], xyz[3 * k + 1] - closest[3 * k + 1]));
      }
    gmsh::finalize();
    return *std::max_element(nearest.begin(), nearest.end());
  }
} // namespace

TEST(SampledBoundaries, SplineVerticesAndMappingPointsOnTheCurve)
{
  const std::string    file     = meshes + "spline_profile_2d.geo";
  const MeshedGeometry geometry = mesh_geometry(file, {});
  ASSERT_EQ(geometry.curved.exact.size(), 2u) << "the BSpline and the Spline are followed";
  EXPECT_TRUE(geometry.curved.straightened.empty());
  for (const auto &curve : geometry.curved.exact)
    EXPECT_EQ(curve.shape, CurvedBoundary::sampled_curve);
  const unsigned int degree = 3;
  EXPECT_EQ(mapping_degree(geometry.curved, degree), degree);

  dealii::Triangulation<2> triangulation;
  create_triangulation(triangulation, geometry, 2, {}, degree);
  const dealii::MappingQ<2>     mapping(degree);
  const dealii::QGaussLobatto<1> support(degree + 1); // where MappingQ puts its points on a line
  const int notch = geometry.boundary_ids.at("notch"), bottom = geometry.boundary_ids.at("bottom");
  std::vector<double> vertices, mapped, chords;
  for (const auto &cell : triangulation.active_cell_iterators())
    for (unsigned int f = 0; f < cell->n_faces(); ++f)
      if (cell->face(f)->at_boundary() &&
          (int(cell->face(f)->boundary_id()) == notch || int(cell->face(f)->boundary_id()) == bottom))
        {
          EXPECT_NE(cell->face(f)->manifold_id(), dealii::numbers::flat_manifold_id);
          for (unsigned int v = 0; v < 2; ++v)
            vertices.insert(vertices.end(), {cell->face(f)->vertex(v)[0], cell->face(f)->vertex(v)[1], 0.});
          for (unsigned int q = 1; q < degree; ++q)
            {
              const auto p = mapping.transform_unit_to_real_cell(cell, on_face(f, support.point(q)[0]));
              mapped.insert(mapped.end(), {p[0], p[1], 0.});
            }
          const auto middle = cell->face(f)->center();
          chords.insert(chords.end(), {middle[0], middle[1], 0.});
        }
  ASSERT_FALSE(vertices.empty());
  const double length   = 10; // the bar's length in the .geo
  const double vertex   = distance_to_curves(file, {1, 3}, vertices);
  const double support_ = distance_to_curves(file, {1, 3}, mapped);
  const double chord    = distance_to_curves(file, {1, 3}, chords);
  std::cout << "spline profile, 2 refinements, degree " << degree << ": " << vertices.size() / 3
            << " vertices, largest distance to gmsh's curve " << vertex / length << " of L; "
            << mapped.size() / 3 << " mapping points: " << support_ / length << "; chord midpoints: "
            << chord / length << "\n";
  EXPECT_LT(vertex, 1e-8 * length);
  EXPECT_LT(support_, 1e-8 * length);
  EXPECT_GT(chord, 1e-5 * length); // the check would see straight faces
}

TEST(SampledBoundaries, EllipseArcsFollowed)
{
  const MeshedGeometry geometry = mesh_geometry(meshes + "elliptical_hole_2d.geo", {});
  ASSERT_EQ(geometry.curved.exact.size(), 2u);
  EXPECT_TRUE(geometry.curved.straightened.empty());
  for (const auto &arc : geometry.curved.exact)
    {
      EXPECT_EQ(arc.shape, CurvedBoundary::sampled_curve);
      // Every sample on x^2/4 + y^2 = 1.
      for (std::size_t i = 0; i < arc.samples.u.size(); ++i)
        {
          const double *x = arc.samples.data.data() + 6 * i;
          EXPECT_NEAR(x[0] * x[0] / 4 + x[1] * x[1], 1, 1e-12);
        }
    }
}

TEST(SampledBoundaries, ExtrudedEllipseSurfaces)
{
  const MeshedGeometry geometry = mesh_geometry(meshes + "elliptical_hole_3d.geo", {});
  ASSERT_EQ(geometry.curved.exact.size(), 2u);
  for (const auto &face : geometry.curved.exact)
    EXPECT_EQ(face.shape, CurvedBoundary::sampled_surface);
  dealii::Triangulation<3> triangulation;
  create_triangulation(triangulation, geometry, 1, {}, 2);
  const dealii::MappingQ<3> mapping(2);
  const int                 hole = geometry.boundary_ids.at("hole");
  double                    vertex = 0, mapped = 0;
  unsigned int              n_faces = 0;
  const auto on_ellipse = [](const dealii::Point<3> &p) { return std::abs(p[0] * p[0] / 4 + p[1] * p[1] - 1); };
  for (const auto &cell : triangulation.active_cell_iterators())
    for (unsigned int f = 0; f < cell->n_faces(); ++f)
      if (cell->face(f)->at_boundary() && int(cell->face(f)->boundary_id()) == hole)
        {
          ++n_faces;
          for (unsigned int v = 0; v < 4; ++v)
            vertex = std::max(vertex, on_ellipse(cell->face(f)->vertex(v)));
          // The face's centre and edge midpoints in the cell's unit coordinates: mapping points.
          const unsigned int normal = f / 2;
          for (const double s : {0., 0.5, 1.})
            for (const double t : {0., 0.5, 1.})
              {
                dealii::Point<3> unit;
                unit[normal]           = f % 2;
                unit[(normal + 1) % 3] = s;
                unit[(normal + 2) % 3] = t;
                mapped = std::max(mapped, on_ellipse(mapping.transform_unit_to_real_cell(cell, unit)));
              }
        }
  std::cout << "extruded ellipse, 1 refinement: " << n_faces << " hole faces, vertices off the ellipse by "
            << vertex << ", mapping points by " << mapped << " (|x^2/4 + y^2 - 1|)\n";
  EXPECT_EQ(n_faces, 6u * 4u); // 6 x 1 faces of the quarter hole, each cut in 4
  EXPECT_LT(vertex, 1e-9);
  EXPECT_LT(mapped, 1e-9);
}
