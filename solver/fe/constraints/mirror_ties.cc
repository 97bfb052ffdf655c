#include "constraints/mirror_ties.h"

#include "constraints/boundary_dof_points.h"
#include "input/expression.h"
#include "input/spec_list.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    std::string point_text(const Point<3> &p, const unsigned int dim)
    {
      std::ostringstream s;
      s << "(";
      for (unsigned int d = 0; d < dim; ++d)
        s << (d ? ", " : "") << p[d];
      s << ")";
      return s.str();
    }

    template <int dim>
    Point<3> as_3d(const Point<dim> &p)
    {
      Point<3> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = p[d];
      return q;
    }

    // 'x y' -> component flags; throws naming the item.
    std::vector<bool> components_of(const std::string &text, const unsigned int dim,
                                    const std::string &context)
    {
      std::vector<bool>  flags(dim, false);
      std::istringstream in(text);
      std::string        c;
      while (in >> c)
        if ((c == "x" || c == "y" || (c == "z" && dim == 3)) && !flags[c[0] - 'x'])
          flags[c[0] - 'x'] = true;
        else
          throw std::invalid_argument(context + ": '" + text + "': expected distinct components " +
                                      (dim == 3 ? "x, y, z" : "x, y") +
                                      " separated by spaces");
      return flags;
    }

    bool line_is(const AffineConstraints<double> &constraints, const types::global_dof_index a,
                 const types::global_dof_index b, const double sign)
    {
      const auto *entries = constraints.get_constraint_entries(a);
      return entries && entries->size() == 1 && (*entries)[0].first == b &&
             (*entries)[0].second == sign && constraints.get_inhomogeneity(a) == 0;
    }

    bool references(const AffineConstraints<double> &constraints, const types::global_dof_index a,
                    const types::global_dof_index b)
    {
      const auto *entries = constraints.get_constraint_entries(a);
      return entries && std::any_of(entries->begin(), entries->end(),
                                    [&](const auto &e) { return e.first == b; });
    }

    bool held_at(const AffineConstraints<double> &constraints, const types::global_dof_index a,
                 double &value)
    {
      const auto *entries = constraints.get_constraint_entries(a);
      value               = constraints.get_inhomogeneity(a);
      return entries && entries->empty();
    }
  } // namespace

  template <int dim>
  void add_mirror_ties(const Discretization<dim> &problem, const std::string &spec,
                       const std::string &where, AffineConstraints<double> &constraints)
  {
    for (const auto &item : parse_spec_list(spec, where))
      {
        const std::string context = where + ": '" + item.name + "'";
        std::vector<bool> even(dim, false), odd(dim, false);
        int               axis = -1;
        double            at   = 0;
        for (const auto &f : item.fields)
          if (f.key == "even")
            even = components_of(f.value, dim, context + ", even");
          else if (f.key == "odd")
            odd = components_of(f.value, dim, context + ", odd");
          else if (f.key == "plane")
            {
              // '<axis> <coordinate>', the coordinate a number or an expression.
              const auto space = f.value.find_first_of(" \t");
              const auto name  = f.value.substr(0, space);
              if (name == "x" || name == "y" || (name == "z" && dim == 3))
                axis = name[0] - 'x';
              if (axis < 0 || space == std::string::npos)
                throw std::invalid_argument(context + ": plane='" + f.value +
                                            "'; expected an axis and a coordinate, e.g. "
                                            "'plane=z 0' for the plane z = 0");
              at = evaluate_expression(trim(f.value.substr(space)), problem.expression_variables(),
                                       context + ", plane");
            }
          else
            throw std::invalid_argument(context + ": unknown field '" + f.key + (f.key.empty() ? "" : "=") +
                                        f.value + "'; expected plane=<axis> <coordinate>, "
                                        "even=<components>, odd=<components>");
        if (axis < 0)
          throw std::invalid_argument(context + " names no mirror plane (e.g. 'plane=z 0')");
        for (unsigned int d = 0; d < dim; ++d)
          if (even[d] && odd[d])
            throw std::invalid_argument(context + ": component " + std::string(1, 'x' + d) +
                                        " is both even and odd");
        if (std::find(even.begin(), even.end(), true) == even.end() &&
            std::find(odd.begin(), odd.end(), true) == odd.end())
          throw std::invalid_argument(context + " ties no component (e.g. 'even=y, odd=z')");

        const auto dof_points =
          boundary_dof_points(problem, boundary_id_of(item.name, problem.geometry.boundary_ids, where));
        // Tolerance for "the same point": the boundary's extent times 1e-9 (support points come
        // from the same mapping, so mirror images agree to round-off on a symmetric mesh).
        double extent = 0;
        for (const auto &[dof, location] : dof_points)
          extent = std::max(extent, location.point.distance(dof_points.begin()->second.point));
        const double tolerance = 1e-9 * std::max(extent, std::abs(at)) + 1e-300;

        // Per component, the boundary's DoFs sorted along the mirror axis's first other
        // coordinate, for a window search.
        const unsigned int key = (axis + 1) % dim;
        std::vector<std::vector<std::pair<Point<dim>, types::global_dof_index>>> by_component(dim);
        for (const auto &[dof, location] : dof_points)
          by_component[location.component].emplace_back(location.point, dof);
        for (auto &list : by_component)
          std::sort(list.begin(), list.end(),
                    [&](const auto &a, const auto &b) { return a.first[key] < b.first[key]; });
        const auto find_mirror = [&](const unsigned int c, const Point<dim> &point,
                                     const Point<dim> &image) {
          const auto &list = by_component[c];
          auto it = std::lower_bound(list.begin(), list.end(), image[key] - tolerance,
                                     [&](const auto &a, const double v) { return a.first[key] < v; });
          for (; it != list.end() && it->first[key] <= image[key] + tolerance; ++it)
            if (it->first.distance(image) <= tolerance)
              return it->second;
          throw std::invalid_argument(context + ": the node at " + point_text(as_3d(point), dim) +
                                      " has no mirror node on the boundary at " +
                                      point_text(as_3d(image), dim) +
                                      " (the mesh must be symmetric about the plane)");
        };

        const auto conflict = [&](const Point<dim> &p) {
          return std::invalid_argument(context + ": the node at " + point_text(as_3d(p), dim) +
                                       " is constrained already in a way the mirror tie "
                                       "contradicts");
        };
        for (const auto &[dof, location] : dof_points)
          {
            const unsigned int c = location.component;
            if (!even[c] && !odd[c])
              continue;
            const double offset = location.point[axis] - at;
            Point<dim>   image  = location.point;
            image[axis]         = at - offset;
            const auto mirror   = find_mirror(c, location.point, image); // also checks the mesh's symmetry
            if (offset < -tolerance)
              continue; // the node on the other side makes the tie
            double value = 0;
            if (std::abs(offset) <= tolerance)
              {
                // On the plane: an odd component is zero, an even one free.
                if (odd[c] && !constraints.is_constrained(dof))
                  constraints.add_line(dof);
                else if (odd[c] && !(held_at(constraints, dof, value) && value == 0))
                  throw conflict(location.point);
                continue;
              }
            // u(dof) = sign u(mirror).
            const double sign = odd[c] ? -1. : 1.;
            const bool   a    = constraints.is_constrained(dof);
            const bool   b    = constraints.is_constrained(mirror);
            if (line_is(constraints, dof, mirror, sign) || line_is(constraints, mirror, dof, sign))
              continue; // the same tie again, e.g. a corner edge shared by two boundaries
            if (!a && !references(constraints, mirror, dof))
              {
                constraints.add_line(dof);
                constraints.add_entry(dof, mirror, sign);
              }
            else if (!b && !references(constraints, dof, mirror))
              {
                constraints.add_line(mirror);
                constraints.add_entry(mirror, dof, sign);
              }
            else
              {
                // Both held at values already: consistent or not.
                double other = 0;
                if (!(held_at(constraints, dof, value) && held_at(constraints, mirror, other) &&
                      value == sign * other))
                  throw conflict(location.point);
              }
          }
      }
  }

  template void add_mirror_ties<2>(const Discretization<2> &, const std::string &,
                                   const std::string &, AffineConstraints<double> &);
  template void add_mirror_ties<3>(const Discretization<3> &, const std::string &,
                                   const std::string &, AffineConstraints<double> &);
} // namespace compliant
