#include "mesh/mesh_size_guard.h"

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <unistd.h>
#include <unordered_map>
#include <vector>

namespace compliant
{
  namespace
  {
    using Point = std::array<double, 3>;

    Point operator-(const Point &a, const Point &b) { return {{a[0] - b[0], a[1] - b[1], a[2] - b[2]}}; }
    Point cross(const Point &a, const Point &b)
    {
      return {{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
    }
    double dot(const Point &a, const Point &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    double norm(const Point &a) { return std::sqrt(dot(a, a)); }

    std::vector<int> entity_tags(const int dim)
    {
      gmsh::vectorpair entities;
      gmsh::model::getEntities(entities, dim);
      std::vector<int> tags;
      for (const auto &[d, tag] : entities)
        tags.push_back(tag);
      return tags;
    }

    // The boundary entities of an entity, signed by their orientation in it.
    gmsh::vectorpair boundary_of(const int dim, const int tag)
    {
      gmsh::vectorpair boundary;
      gmsh::model::getBoundary({{dim, tag}}, boundary, false, true, false);
      return boundary;
    }

    // The {a, b, c} list after `keyword` in a line of a .geo_unrolled file.
    std::vector<int> braced_tags(const std::string &line)
    {
      std::vector<int> tags;
      const auto       open = line.find('{'), close = line.find('}');
      if (open == std::string::npos || close == std::string::npos || close < open)
        return tags;
      std::stringstream list(line.substr(open + 1, close - open - 1));
      std::string       item;
      while (std::getline(list, item, ','))
        try
          {
            tags.push_back(std::abs(std::stoi(item)));
          }
        catch (const std::exception &)
          {
          }
      return tags;
    }

    // The mesh of an entity, summed up: cells, edges and their length, and a moment: for a curve,
    // sum of x_a x x_b over its segments (twice the area vector its segments sweep about the
    // origin); for a surface, sum of centroid . area vector over its faces (three times the
    // volume they enclose with the origin).
    struct MeshSummary
    {
      double cells = 0, edges = 0, edge_length = 0;
      double quadrilaterals = 0;
      Point  moment = {{0, 0, 0}};
    };

    MeshSummary summarize_mesh(const int dim, const int tag)
    {
      std::vector<std::size_t> node_tags;
      std::vector<double>      coordinates, parametric;
      gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, dim, tag, true, false);
      std::unordered_map<std::size_t, Point> position;
      for (std::size_t i = 0; i < node_tags.size(); ++i)
        position[node_tags[i]] = {{coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]}};

      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> element_tags, element_nodes;
      gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, tag);
      MeshSummary summary;
      for (std::size_t t = 0; t < types.size(); ++t)
        {
          std::string         name;
          int                 element_dim, order, n_nodes, n_corners;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(types[t], name, element_dim, order, n_nodes, local, n_corners);
          if (element_dim != dim || n_corners < 2)
            continue;
          for (std::size_t e = 0; e < element_tags[t].size(); ++e)
            {
              std::vector<Point> x;
              for (int c = 0; c < n_corners; ++c)
                x.push_back(position[element_nodes[t][e * n_nodes + c]]);
              summary.cells += 1;
              const int n_edges = dim == 1 ? 1 : n_corners;
              for (int c = 0; c < n_edges; ++c)
                summary.edge_length += norm(x[(c + 1) % n_corners] - x[c]);
              summary.edges += n_edges;
              if (dim == 1)
                {
                  const Point m = cross(x[0], x[1]);
                  for (int i = 0; i < 3; ++i)
                    summary.moment[i] += m[i];
                  continue;
                }
              summary.quadrilaterals += n_corners == 4;
              for (int c = 1; c + 1 < n_corners; ++c) // a fan of triangles
                {
                  const Point area     = cross(x[c] - x[0], x[c + 1] - x[0]);
                  const Point centroid = {{(x[0][0] + x[c][0] + x[c + 1][0]) / 3,
                                           (x[0][1] + x[c][1] + x[c + 1][1]) / 3,
                                           (x[0][2] + x[c][2] + x[c + 1][2]) / 3}};
                  summary.moment[0] += 0.5 * dot(centroid, area);
                }
            }
        }
      return summary;
    }

    bool is_recombined(const int surface, const MeshConstraints &c)
    {
      return c.recombine_all || c.recombined_surfaces.count(surface) > 0;
    }

    // A transfinite block's cells from the sorted segment counts of its sides, which come in
    // equal pairs (a surface's 4 curves, a volume's 6 faces) or fours (a volume's 12 edges).
    std::optional<double> structured_cells(std::vector<double> counts, const std::size_t group,
                                           const std::size_t n_groups)
    {
      if (counts.size() != group * n_groups)
        return std::nullopt;
      std::sort(counts.begin(), counts.end());
      double cells = 1;
      for (std::size_t i = 0; i < counts.size(); i += group)
        cells *= counts[i];
      return cells;
    }

    // Surface cells from the segment counts of its curves (known: those in `segments`), and, where
    // the curves are meshed, from the area they enclose.
    double surface_cells(const int surface, const MeshConstraints &c, const std::map<int, double> &segments,
                         const std::map<int, MeshSummary> *curve_meshes)
    {
      std::vector<double> counts;
      double              known = 0, edges = 0, length = 0;
      Point               area  = {{0, 0, 0}};
      for (const auto &[dim, signed_tag] : boundary_of(2, surface))
        {
          const auto found = segments.find(std::abs(signed_tag));
          if (found == segments.end())
            continue;
          counts.push_back(found->second);
          known += found->second;
          if (!curve_meshes)
            continue;
          const MeshSummary &m = curve_meshes->at(std::abs(signed_tag));
          edges += m.edges;
          length += m.edge_length;
          for (int i = 0; i < 3; ++i)
            area[i] += (signed_tag < 0 ? -0.5 : 0.5) * m.moment[i];
        }
      const double per_quadrilateral = is_recombined(surface, c) ? 1 : 2;
      if (c.transfinite_surfaces.count(surface) && counts.size() == boundary_of(2, surface).size())
        if (const auto cells = structured_cells(counts, 2, 2))
          return per_quadrilateral * *cells;
      if (!curve_meshes || edges == 0)
        return known / 2; // a floor: every boundary segment borders a cell, at most two per cell
      const double h = length / edges;
      return std::max(known / 2, (is_recombined(surface, c) ? 1.15 : 2.31) * norm(area) / (h * h));
    }

    // The curves bounding a volume (its 12 edges for a hexahedral block).
    std::vector<int> edges_of_volume(const int volume)
    {
      std::set<int> curves;
      for (const auto &[dim, face] : boundary_of(3, volume))
        for (const auto &[d, curve] : boundary_of(2, std::abs(face)))
          curves.insert(std::abs(curve));
      return {curves.begin(), curves.end()};
    }

    // 3D: transfinite volumes from their edges' counts, and at least half the boundary's faces.
    double volume_cells_from_curves(const MeshConstraints &c, const std::map<int, double> &segments,
                                    const std::map<int, MeshSummary> *curve_meshes)
    {
      double faces = 0, blocks = 0;
      for (const int surface : entity_tags(2))
        faces += surface_cells(surface, c, segments, curve_meshes);
      for (const int volume : c.transfinite_volumes)
        {
          std::vector<double> counts;
          for (const int curve : edges_of_volume(volume))
            if (segments.count(curve))
              counts.push_back(segments.at(curve));
          if (const auto cells = structured_cells(counts, 4, 3))
            blocks += *cells;
        }
      return std::max(blocks, faces / 2);
    }
  } // namespace

  MeshConstraints read_mesh_constraints()
  {
    MeshConstraints constraints;
    double recombine_all = 0;
    gmsh::option::getNumber("Mesh.RecombineAll", recombine_all);
    constraints.recombine_all = recombine_all != 0;
    char      name[] = "/tmp/compliant-constraints-XXXXXX.geo_unrolled";
    const int fd     = mkstemps(name, 13);
    if (fd < 0)
      return constraints;
    close(fd);
    gmsh::write(name);
    std::ifstream in(name);
    std::string   line;
    while (std::getline(in, line))
      {
        const auto tags = braced_tags(line);
        if (line.rfind("Transfinite Line", 0) == 0 || line.rfind("Transfinite Curve", 0) == 0)
          {
            const auto equals = line.find('=', line.find('}'));
            if (equals == std::string::npos)
              continue;
            const double points = std::atof(line.c_str() + equals + 1);
            for (const int tag : tags)
              constraints.transfinite_curves[tag] = std::max(1.0, points - 1);
          }
        else if (line.rfind("Transfinite Surface", 0) == 0)
          constraints.transfinite_surfaces.insert(tags.begin(), tags.end());
        else if (line.rfind("Transfinite Volume", 0) == 0)
          constraints.transfinite_volumes.insert(tags.begin(), tags.end());
        else if (line.rfind("Recombine Surface", 0) == 0)
          constraints.recombined_surfaces.insert(tags.begin(), tags.end());
      }
    std::remove(name);
    return constraints;
  }

  CellEstimate estimate_cells_before_meshing(const int dimension, const MeshConstraints &c)
  {
    CellEstimate estimate{0, "the transfinite curves"};
    if (dimension == 3)
      estimate.cells = volume_cells_from_curves(c, c.transfinite_curves, nullptr);
    else
      for (const int surface : entity_tags(2))
        estimate.cells += surface_cells(surface, c, c.transfinite_curves, nullptr);
    return estimate;
  }

  CellEstimate estimate_cells_from_curves(const int dimension, const MeshConstraints &c)
  {
    std::map<int, MeshSummary> meshes;
    std::map<int, double>      segments;
    for (const int curve : entity_tags(1))
      {
        meshes[curve]   = summarize_mesh(1, curve);
        segments[curve] = meshes[curve].cells;
      }
    CellEstimate estimate{0, "the curve meshes"};
    if (dimension == 3)
      estimate.cells = volume_cells_from_curves(c, segments, &meshes);
    else
      for (const int surface : entity_tags(2))
        estimate.cells += surface_cells(surface, c, segments, &meshes);
    return estimate;
  }

  CellEstimate estimate_cells_from_surfaces(const MeshConstraints &c)
  {
    std::map<int, MeshSummary> faces;
    for (const int surface : entity_tags(2))
      faces[surface] = summarize_mesh(2, surface);
    CellEstimate estimate{0, "the surface meshes"};
    for (const int volume : entity_tags(3))
      {
        const auto          boundary = boundary_of(3, volume);
        double              enclosed = 0, edges = 0, length = 0, quadrilaterals = 0, n_faces = 0;
        std::vector<double> counts;
        for (const auto &[dim, signed_tag] : boundary)
          {
            const MeshSummary &m = faces.at(std::abs(signed_tag));
            enclosed += (signed_tag < 0 ? -1.0 : 1.0) * m.moment[0] / 3;
            edges += m.edges;
            length += m.edge_length;
            quadrilaterals += m.quadrilaterals;
            n_faces += m.cells;
            counts.push_back(m.quadrilaterals > 0 ? m.cells : m.cells / 2);
          }
        const bool hexahedral = quadrilaterals == n_faces;
        if (c.transfinite_volumes.count(volume) && counts.size() == 6)
          if (const auto squared = structured_cells(counts, 2, 3))
            {
              estimate.cells += (hexahedral ? 1 : 6) * std::sqrt(*squared);
              continue;
            }
        const double h = edges > 0 ? length / edges : 0;
        if (h > 0)
          estimate.cells += std::max(n_faces / 4, (hexahedral ? 1 : 8.5) * std::abs(enclosed) / (h * h * h));
      }
    return estimate;
  }
} // namespace compliant
