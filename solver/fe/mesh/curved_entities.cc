#include "mesh/curved_entities.h"

#include "mesh/gmsh_sampling.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace compliant
{
  namespace
  {
    using Point = std::array<double, 3>;

    Point  minus(const Point &a, const Point &b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
    double dot(const Point &a, const Point &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    double norm(const Point &a) { return std::sqrt(dot(a, a)); }
    Point  cross(const Point &a, const Point &b)
    {
      return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
    }

    // Geometry from gmsh holds to about 1e-8 of its size (built-in kernel extrusions drift that
    // much from their plane): a shape whose samples miss it by more than 1e-6 (relative to its
    // radius or size) is something else (an ellipse, a spline); flatter than that is straight.
    constexpr double shape_tolerance = 1e-6;

    // Solves the n x n system a x = b (row-major) by elimination with partial pivoting; false if
    // it is singular to round-off.
    bool solve(std::vector<double> a, std::vector<double> b, const unsigned int n, std::vector<double> &x)
    {
      for (unsigned int k = 0; k < n; ++k)
        {
          unsigned int pivot = k;
          for (unsigned int i = k + 1; i < n; ++i)
            if (std::abs(a[i * n + k]) > std::abs(a[pivot * n + k]))
              pivot = i;
          if (std::abs(a[pivot * n + k]) < 1e-13)
            return false;
          for (unsigned int j = 0; j < n; ++j)
            std::swap(a[k * n + j], a[pivot * n + j]);
          std::swap(b[k], b[pivot]);
          for (unsigned int i = k + 1; i < n; ++i)
            {
              const double factor = a[i * n + k] / a[k * n + k];
              for (unsigned int j = k; j < n; ++j)
                a[i * n + j] -= factor * a[k * n + j];
              b[i] -= factor * b[k];
            }
        }
      x.assign(n, 0.);
      for (int i = n - 1; i >= 0; --i)
        {
          double sum = b[i];
          for (unsigned int j = i + 1; j < n; ++j)
            sum -= a[i * n + j] * x[j];
          x[i] = sum / a[i * n + i];
        }
      return true;
    }

    // Algebraic least-squares fit of |p - c|^2 = r^2 over the first n_coordinates coordinates
    // (2: a circle in a plane, 3: a sphere), on points shifted and scaled for conditioning.
    // Returns false when the points do not lie on such a shape to shape_tolerance.
    bool fit_sphere(const std::vector<Point> &points, const unsigned int n_coordinates,
                    Point &centre, double &radius)
    {
      Point mean = {{0, 0, 0}};
      for (const auto &p : points)
        for (unsigned int d = 0; d < 3; ++d)
          mean[d] += p[d] / points.size();
      double scale = 0;
      for (const auto &p : points)
        scale = std::max(scale, norm(minus(p, mean)));
      if (!(scale > 0))
        return false;
      // Unknowns: the centre (scaled) and k = r^2 - |c|^2; |p|^2 = 2 c.p + k.
      const unsigned int  n = n_coordinates + 1;
      std::vector<double> normal_matrix(n * n, 0.), rhs(n, 0.), row(n), solution;
      for (const auto &p : points)
        {
          double squared = 0;
          for (unsigned int d = 0; d < n_coordinates; ++d)
            {
              const double q = (p[d] - mean[d]) / scale;
              row[d]         = 2 * q;
              squared += q * q;
            }
          row[n_coordinates] = 1;
          for (unsigned int i = 0; i < n; ++i)
            {
              rhs[i] += row[i] * squared;
              for (unsigned int j = 0; j < n; ++j)
                normal_matrix[i * n + j] += row[i] * row[j];
            }
        }
      if (!solve(normal_matrix, rhs, n, solution))
        return false;
      double centre_squared = 0;
      for (unsigned int d = 0; d < n_coordinates; ++d)
        centre_squared += solution[d] * solution[d];
      const double radius_squared = solution[n_coordinates] + centre_squared;
      if (!(radius_squared > 0))
        return false;
      radius = std::sqrt(radius_squared) * scale;
      centre = mean;
      for (unsigned int d = 0; d < n_coordinates; ++d)
        centre[d] += solution[d] * scale;
      for (const auto &p : points)
        {
          Point offset = minus(p, centre);
          for (unsigned int d = n_coordinates; d < 3; ++d)
            offset[d] = 0;
          if (std::abs(norm(offset) - radius) > shape_tolerance * radius)
            return false;
        }
      return true;
    }

    std::vector<Point> as_points(const std::vector<double> &xyz)
    {
      std::vector<Point> points(xyz.size() / 3);
      for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {{xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]}};
      return points;
    }

    double extent(const std::vector<Point> &points)
    {
      double largest = 0;
      for (const auto &p : points)
        largest = std::max(largest, norm(minus(p, points.front())));
      return largest;
    }

    // Samples of a curve of the xy plane: the circle's shape if it is one, else -1 for a straight
    // line and -2 for another curve.
    int classify_curve(const int tag, CurvedBoundary &boundary)
    {
      std::vector<double> min, max;
      gmsh::model::getParametrizationBounds(1, tag, min, max);
      if (min.size() != 1 || !(max[0] > min[0]))
        return -1;
      std::vector<double> parameters, xyz;
      for (int i = 0; i <= 16; ++i)
        parameters.push_back(min[0] + (max[0] - min[0]) * i / 16.);
      gmsh::model::getValue(1, tag, parameters, xyz);
      const auto points = as_points(xyz);
      const double size = extent(points);
      if (!(size > 0))
        return -1;
      // Straight when every sample lies on the line through the first and the farthest one.
      const auto farthest = *std::max_element(points.begin(), points.end(), [&](const Point &a, const Point &b) {
        return norm(minus(a, points.front())) < norm(minus(b, points.front()));
      });
      const Point direction = minus(farthest, points.front());
      double      off_line  = 0;
      for (const auto &p : points)
        off_line = std::max(off_line, norm(cross(minus(p, points.front()), direction)) / norm(direction));
      if (off_line <= 1e-6 * size)
        return -1;
      Point  centre;
      double radius;
      if (!fit_sphere(points, 2, centre, radius))
        return -2;
      boundary.shape  = CurvedBoundary::circle;
      boundary.radius = radius;
      std::copy(centre.begin(), centre.end(), boundary.centre);
      return boundary.shape;
    }

    int classify_surface(const int tag, CurvedBoundary &boundary)
    {
      std::vector<double> min, max;
      gmsh::model::getParametrizationBounds(2, tag, min, max);
      if (min.size() != 2 || !(max[0] > min[0]) || !(max[1] > min[1]))
        return -1;
      std::vector<double> parameters, xyz, normal_values;
      constexpr int       n = 6;
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
          {
            parameters.push_back(min[0] + (max[0] - min[0]) * i / n);
            parameters.push_back(min[1] + (max[1] - min[1]) * j / n);
          }
      gmsh::model::getValue(2, tag, parameters, xyz);
      gmsh::model::getNormal(tag, parameters, normal_values);
      const auto points  = as_points(xyz);
      const auto normals = as_points(normal_values);
      const double size  = extent(points);
      if (!(size > 0) || normals.size() != points.size())
        return -1;

      // Parametrizations may collapse an edge (a triangular patch), where the normal vanishes:
      // the longest normal is the reference, and vanishing ones take no part.
      double longest = 0;
      Point  reference{{0, 0, 0}};
      for (const auto &normal : normals)
        if (norm(normal) > longest)
          longest = norm(normal), reference = normal;
      if (!(longest > 0))
        return -2;
      // Planar: every sample in the plane through the first one across the reference normal.
      bool planar = true;
      for (const auto &p : points)
        planar = planar && std::abs(dot(minus(p, points.front()), reference)) <= 1e-6 * size * longest;
      if (planar)
        return -1;

      Point  centre;
      double radius;
      if (fit_sphere(points, 3, centre, radius))
        {
          boundary.shape  = CurvedBoundary::sphere;
          boundary.radius = radius;
          std::copy(centre.begin(), centre.end(), boundary.centre);
          return boundary.shape;
        }

      // A cylinder: every normal is perpendicular to the axis, and the samples projected on a
      // plane across the axis lie on a circle.
      Point  axis    = {{0, 0, 0}};
      double largest = 0;
      for (const auto &normal : normals)
        {
          const Point candidate = cross(reference, normal);
          if (norm(candidate) > largest)
            largest = norm(candidate), axis = candidate;
        }
      if (!(largest > 1e-6 * longest * longest))
        return -2;
      const double axis_norm = norm(axis);
      for (auto &a : axis)
        a /= axis_norm;
      for (const auto &normal : normals)
        if (norm(normal) > 1e-6 * longest && std::abs(dot(normal, axis)) > shape_tolerance * norm(normal))
          return -2;
      const Point helper = std::abs(axis[0]) < 0.9 ? Point{{1, 0, 0}} : Point{{0, 1, 0}};
      Point       e1     = cross(axis, helper);
      const double e1_norm = norm(e1);
      for (auto &e : e1)
        e /= e1_norm;
      const Point        e2 = cross(axis, e1);
      std::vector<Point> projected;
      for (const auto &p : points)
        projected.push_back({{dot(p, e1), dot(p, e2), 0}});
      Point plane_centre;
      if (!fit_sphere(projected, 2, plane_centre, radius))
        return -2;
      boundary.shape  = CurvedBoundary::cylinder;
      boundary.radius = radius;
      for (unsigned int d = 0; d < 3; ++d)
        {
          boundary.centre[d] = plane_centre[0] * e1[d] + plane_centre[1] * e2[d];
          boundary.axis[d]   = axis[d];
        }
      return boundary.shape;
    }

    // The vertex centre of every mesh element of the entity: how the deal.II side finds its faces.
    std::vector<double> element_centres(const int dim, const int tag,
                                        const std::unordered_map<std::size_t, std::size_t> &node_index,
                                        const std::vector<double> &node_xyz)
    {
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags, node_tags;
      gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, tag);
      std::vector<double> centres;
      for (std::size_t t = 0; t < types.size(); ++t)
        {
          std::string         name;
          int                 element_dim, order, n_nodes, n_primary;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(types[t], name, element_dim, order, n_nodes, local, n_primary);
          for (std::size_t e = 0; e < element_tags[t].size(); ++e)
            {
              double c[3] = {0, 0, 0};
              for (int v = 0; v < n_primary; ++v)
                {
                  const std::size_t index = node_index.at(node_tags[t][e * n_nodes + v]);
                  for (unsigned int d = 0; d < 3; ++d)
                    c[d] += node_xyz[3 * index + d] / n_primary;
                }
              centres.insert(centres.end(), c, c + 3);
            }
        }
      return centres;
    }
  } // namespace

  CurvedEntities find_curved_entities(const int dimension)
  {
    CurvedEntities result;
    if (dimension != 2 && dimension != 3)
      return result;
    std::vector<std::size_t> node_tags;
    std::vector<double>      node_xyz, unused;
    gmsh::model::mesh::getNodes(node_tags, node_xyz, unused, -1, -1, false, false);
    std::unordered_map<std::size_t, std::size_t> node_index;
    for (std::size_t i = 0; i < node_tags.size(); ++i)
      node_index[node_tags[i]] = i;

    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, dimension - 1);
    for (const auto &[dim, tag] : entities)
      {
        std::string type;
        gmsh::model::getType(dim, tag, type);
        if (type.find("Discrete") != std::string::npos)
          continue; // a .msh file's entity: no geometry behind the mesh
        CurvedBoundary boundary;
        boundary.entity = tag;
        int         shape = -2;
        std::string why   = "gmsh cannot evaluate its parametrization";
        try
          {
            shape = dim == 1 ? classify_curve(tag, boundary) : classify_surface(tag, boundary);
          }
        catch (...) // gmsh cannot evaluate this entity: keep its faces straight, and say so
          {
            shape = -3;
          }
        if (shape == -1)
          continue;
        if (shape == -2) // curved, and neither circle, cylinder nor sphere: follow its samples
          {
            why   = sample_entity(dim, tag, boundary.samples);
            shape = why.empty() ? (dim == 1 ? CurvedBoundary::sampled_curve : CurvedBoundary::sampled_surface) : -3;
            boundary.shape = shape;
          }
        if (shape == -3)
          {
            result.straightened.push_back((dim == 1 ? "curve " : "surface ") + std::to_string(tag) +
                                          " (" + type + "): " + why);
            continue;
          }
        boundary.face_centres = element_centres(dim, tag, node_index, node_xyz);
        if (!boundary.face_centres.empty())
          result.exact.push_back(std::move(boundary));
      }
    return result;
  }
} // namespace compliant
