#include "section/boundary_corners.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace compliant::section
{
  using namespace dealii;

  namespace
  {
    struct BoundaryEdgeEnd
    {
      Point<2>     other_end;
      Tensor<1, 2> outward_normal;
    };
  } // namespace

  std::vector<BoundaryCorner> reentrant_corners(const Triangulation<2> &triangulation,
                                                const double            min_excess)
  {
    std::map<unsigned int, std::vector<BoundaryEdgeEnd>> edges_at_vertex;
    std::map<unsigned int, double>                       cell_size_at_vertex;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto     face = cell->face(f);
            const Point<2> v0 = face->vertex(0), v1 = face->vertex(1);
            Tensor<1, 2>   normal({v1[1] - v0[1], v0[0] - v1[0]});
            if (normal * (face->center() - cell->center()) < 0)
              normal = -normal;
            for (unsigned int i = 0; i < 2; ++i)
              {
                const unsigned int vertex = face->vertex_index(i);
                edges_at_vertex[vertex].push_back({i == 0 ? v1 : v0, normal});
                cell_size_at_vertex[vertex] =
                  std::max(cell_size_at_vertex[vertex], cell->diameter());
              }
          }

    std::vector<BoundaryCorner> corners;
    for (const auto &[vertex, edges] : edges_at_vertex)
      {
        if (edges.size() != 2) // a vertex where the boundary touches itself: not a plain corner
          continue;
        const Point<2>     p  = triangulation.get_vertices()[vertex];
        const Tensor<1, 2> d1 = edges[0].other_end - p, d2 = edges[1].other_end - p;
        const double       between =
          std::acos(std::clamp(d1 * d2 / (d1.norm() * d2.norm()), -1.0, 1.0));
        // The second edge leaves towards the outer side of the first one: the material wraps
        // around the vertex by more than pi.
        const bool   concave  = d2 * edges[0].outward_normal > 0;
        const double interior = concave ? 2 * M_PI - between : between;
        if (interior > M_PI + min_excess)
          corners.push_back({p, interior, cell_size_at_vertex[vertex]});
      }
    return corners;
  }
} // namespace compliant::section
