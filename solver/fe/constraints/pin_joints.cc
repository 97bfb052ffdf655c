#include "constraints/pin_joints.h"

#include "constraints/boundary_dof_points.h"
#include "input/spec_list.h"

#include <algorithm>
#include <array>
#include <set>
#include <cmath>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // The DoFs of one node of a ring, by component.
    template <int dim>
    struct RingNode
    {
      Point<dim>                                 point;
      std::array<types::global_dof_index, dim> dofs;
    };

    template <int dim>
    std::vector<RingNode<dim>> ring_nodes(const Discretization<dim> &problem,
                                          const std::string &name, const std::string &where)
    {
      const auto dof_points =
        boundary_dof_points(problem, boundary_id_of(name, problem.geometry.boundary_ids, where));
      // DoFs of the same node share the support point exactly (same cell computation).
      std::vector<RingNode<dim>>          nodes;
      std::vector<std::vector<bool>>      seen;
      for (const auto &[dof, location] : dof_points)
        {
          auto it = std::find_if(nodes.begin(), nodes.end(), [&](const RingNode<dim> &n) {
            return n.point.distance(location.point) < 1e-12 * (1 + location.point.norm());
          });
          if (it == nodes.end())
            {
              nodes.push_back({location.point, {}});
              it = std::prev(nodes.end());
            }
          it->dofs[location.component] = dof;
        }
      return nodes;
    }
  } // namespace

  template <int dim>
  void add_pin_joints(const Discretization<dim> &problem, const std::string &spec,
                      const std::string &where, AffineConstraints<double> &constraints)
  {
    std::set<types::global_dof_index> tied; // eye DoFs already made dependent
    for (const auto &item : parse_spec_list(spec, where))
      {
        // Boundary names, and optionally joint=pin (default) or joint=bonded.
        bool                     bonded = false;
        std::vector<std::string> rings;
        for (const auto &f : item.fields)
          if (f.key.empty())
            rings.push_back(f.value);
          else if (f.key == "joint" && (f.value == "pin" || f.value == "bonded"))
            bonded = f.value == "bonded";
          else
            throw std::invalid_argument(where + ": pin '" + item.name + "': unknown field '" +
                                        f.key + "=" + f.value +
                                        "'; expected boundary names and joint=pin|bonded");
        if (rings.size() < 2)
          throw std::invalid_argument(where + ": pin '" + item.name +
                                      "' needs the pin's boundary and at least one eye");
        const auto pin = ring_nodes(problem, rings[0], where);
        Point<dim> center;
        for (const auto &n : pin)
          center += n.point / static_cast<double>(pin.size());
        double radius = 0;
        for (const auto &n : pin)
          radius = std::max(radius, n.point.distance(center));
        // Meshes may offset bodies slightly to keep coincident circles apart (jansen_leg.geo).
        const double tolerance = 1e-3 * radius;

        for (unsigned int e = 1; e < rings.size(); ++e)
          {
            const std::string eye_name = rings[e];
            const auto        eye      = ring_nodes(problem, eye_name, where);
            if (eye.size() != pin.size())
              throw std::invalid_argument(
                where + ": eye '" + eye_name + "' has " + std::to_string(eye.size()) +
                " nodes on its circle, pin '" + rings[0] + "' has " +
                std::to_string(pin.size()) + "; mesh both circles with the same nodes");
            bool spin_fixed = e != 1; // only the first eye takes the pin's spin
            bool axis_held  = false;  // 3D: one node holds the eye along the pin's axis
            for (const auto &node : eye)
              {
                const auto match = std::find_if(pin.begin(), pin.end(), [&](const RingNode<dim> &n) {
                  return n.point.distance(node.point) < tolerance;
                });
                if (match == pin.end())
                  throw std::invalid_argument(where + ": node (" + std::to_string(node.point[0]) +
                                              ", " + std::to_string(node.point[1]) + ") of eye '" +
                                              eye_name + "' has no node of pin '" +
                                              rings[0] + "' at the same place");
                for (const auto dof : node.dofs)
                  if (constraints.is_constrained(dof) || tied.count(dof))
                    throw std::invalid_argument(where + ": eye '" + eye_name +
                                                "' is supported or in another pin; support the "
                                                "pin's boundary instead");
                // Radial direction in the plane of the linkage (x, y).
                Tensor<1, dim> normal;
                for (unsigned int d = 0; d < 2; ++d)
                  normal[d] = node.point[d] - center[d];
                normal /= normal.norm();
                // Bonded: every node tied fully (a welded joint, for comparison with models
                // that glue their links together).
                const bool full_tie =
                  bonded || (!spin_fixed && !constraints.is_constrained(match->dofs[0]) &&
                             !constraints.is_constrained(match->dofs[1]));
                if (full_tie)
                  {
                    for (unsigned int d = 0; d < dim; ++d)
                      {
                        constraints.add_line(node.dofs[d]);
                        constraints.add_entry(node.dofs[d], match->dofs[d], 1.0);
                      }
                    spin_fixed = true;
                    axis_held  = true;
                  }
                else
                  {
                    // u_eye . n = u_pin . n, solved for the eye's component with the larger |n_k|.
                    const unsigned int k = std::abs(normal[0]) >= std::abs(normal[1]) ? 0 : 1;
                    constraints.add_line(node.dofs[k]);
                    for (unsigned int d = 0; d < 2; ++d)
                      {
                        constraints.add_entry(node.dofs[k], match->dofs[d], normal[d] / normal[k]);
                        if (d != k)
                          constraints.add_entry(node.dofs[k], node.dofs[d], -normal[d] / normal[k]);
                      }
                    // 3D: the pin holds the eye along its axis at one node; radial ties at every
                    // height already stop the eye tilting. Tying z everywhere would also stop the
                    // hole's Poisson contraction through the thickness and raise the stress there.
                    if (dim == 3 && !axis_held)
                      {
                        constraints.add_line(node.dofs[dim - 1]);
                        constraints.add_entry(node.dofs[dim - 1], match->dofs[dim - 1], 1.0);
                        axis_held = true;
                      }
                  }
                for (const auto dof : node.dofs)
                  tied.insert(dof);
              }
          }
      }
  }

  template void add_pin_joints<2>(const Discretization<2> &, const std::string &,
                                  const std::string &, AffineConstraints<double> &);
  template void add_pin_joints<3>(const Discretization<3> &, const std::string &,
                                  const std::string &, AffineConstraints<double> &);
} // namespace compliant
