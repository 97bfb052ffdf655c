#include "mesh/interior_boundaries.h"

#include <gmsh.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <unordered_set>
#include <vector>

namespace compliant
{
  namespace
  {
    using FaceKey = std::vector<std::size_t>; // sorted corner nodes

    // A group's entities between two meshed regions of the body, from gmsh's topology.
    void refuse_by_topology(const std::string &file, const MeshedGeometry &result, const std::set<int> &body)
    {
      const int        dim = result.dimension;
      std::vector<int> entities;
      for (const auto &[name, tag] : result.boundary_ids)
        {
          gmsh::model::getEntitiesForPhysicalGroup(dim - 1, tag, entities);
          for (const int entity : entities)
            {
              std::vector<int> upward, downward;
              gmsh::model::getAdjacencies(dim - 1, entity, upward, downward);
              std::vector<int> sides;
              for (const int region : upward)
                if (body.count(region))
                  sides.push_back(region);
              if (sides.size() >= 2)
                throw std::runtime_error(
                  "geometry file '" + file + "': boundary group '" + name + "' holds " +
                  (dim == 3 ? "surface " : "curve ") + std::to_string(entity) + ", which lies inside the body (between " +
                  (dim == 3 ? "volumes " : "surfaces ") + std::to_string(sides[0]) + " and " + std::to_string(sides[1]) +
                  "); boundary conditions and loads act on the outer boundary only: take it out of the group");
            }
        }
    }

    // A boundary group's element face (edge in 2D) and how many cells of the body hold it.
    struct FaceUse
    {
      const std::string *group;
      unsigned int       cells = 0;
    };
    using FaceUses = std::map<FaceKey, FaceUse>;

    // The elements of entity (dim, tag) of `group`, by their sorted corner nodes, into `uses`.
    void add_group_faces(const int dim, const int tag, const std::string &group, FaceUses &uses)
    {
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> tags, nodes;
      gmsh::model::mesh::getElements(types, tags, nodes, dim, tag);
      for (unsigned int t = 0; t < types.size(); ++t)
        {
          std::string         name;
          int                 element_dim, order, n_nodes, n_corners;
          std::vector<double> local;
          gmsh::model::mesh::getElementProperties(types[t], name, element_dim, order, n_nodes, local, n_corners);
          for (std::size_t e = 0; e < tags[t].size(); ++e)
            {
              FaceKey key(nodes[t].begin() + e * n_nodes, nodes[t].begin() + e * n_nodes + n_corners);
              std::sort(key.begin(), key.end());
              uses.try_emplace(std::move(key), FaceUse{&group});
            }
        }
    }

    // How many cells of the body's entities hold each of `wanted`'s faces (edges in 2D). A face
    // with a corner that is no corner of a wanted face is skipped before any key is made: on a
    // mesh of 1e6 cells nearly all are.
    void count_cell_faces(const int dim, const std::set<int> &body, FaceUses &wanted)
    {
      std::unordered_set<std::size_t> corners_wanted;
      for (const auto &[key, n] : wanted)
        corners_wanted.insert(key.begin(), key.end());
      FaceKey key;
      for (const int entity : body)
        {
          std::vector<int> types;
          gmsh::model::mesh::getElementTypes(types, dim, entity);
          for (const int type : types)
            for (const int corners : dim == 2 ? std::vector<int>{2} : std::vector<int>{3, 4})
              {
                std::vector<std::size_t> face_nodes;
                if (dim == 2)
                  gmsh::model::mesh::getElementEdgeNodes(type, face_nodes, entity, true);
                else
                  gmsh::model::mesh::getElementFaceNodes(type, corners, face_nodes, entity, true);
                for (std::size_t f = 0; f + corners <= face_nodes.size(); f += corners)
                  {
                    const auto first = face_nodes.begin() + f, last = first + corners;
                    if (!std::all_of(first, last, [&](const std::size_t node) { return corners_wanted.count(node); }))
                      continue;
                    key.assign(first, last);
                    std::sort(key.begin(), key.end());
                    if (const auto found = wanted.find(key); found != wanted.end())
                      ++found->second.cells;
                  }
              }
        }
    }

    // A group's element faces that two cells of the body share, from the mesh alone.
    void refuse_by_mesh(const std::string &file, const MeshedGeometry &result, const std::set<int> &body)
    {
      const int                          dim = result.dimension;
      FaceUses         uses;
      std::vector<int> entities;
      for (const auto &[name, tag] : result.boundary_ids)
        {
          gmsh::model::getEntitiesForPhysicalGroup(dim - 1, tag, entities);
          for (const int entity : entities)
            add_group_faces(dim - 1, entity, name, uses);
        }
      if (uses.empty())
        return;
      count_cell_faces(dim, body, uses);
      for (const auto &[key, use] : uses)
        if (use.cells >= 2)
          {
            std::vector<double> x, parametric;
            gmsh::model::mesh::getNode(key.front(), x, parametric);
            char where[96];
            std::snprintf(where, sizeof(where), "(%g, %g, %g)", x[0], x[1], x[2]);
            throw std::runtime_error("geometry file '" + file + "': boundary group '" + *use.group +
                                     "' holds " + (dim == 3 ? "element faces" : "element edges") +
                                     " inside the body, shared by two cells (one with a corner at " + where +
                                     "); boundary conditions and loads act on the outer boundary only: take "
                                     "them out of the group");
          }
    }
  } // namespace

  void refuse_interior_boundaries(const std::string &file, const MeshedGeometry &result)
  {
    std::set<int>    body;
    std::vector<int> entities;
    for (const auto &[name, tag] : result.material_ids)
      {
        gmsh::model::getEntitiesForPhysicalGroup(result.dimension, tag, entities);
        body.insert(entities.begin(), entities.end());
      }
    refuse_by_topology(file, result, body);
    refuse_by_mesh(file, result, body);
  }
} // namespace compliant
