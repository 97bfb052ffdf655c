#include "constraints/edge_supports.h"

#include "constraints/boundary_dof_points.h"
#include "input/spec_list.h"

namespace compliant
{
  template <int dim>
  void add_edge_supports(const Discretization<dim> &problem, const std::string &spec,
                         const std::string &where, dealii::AffineConstraints<double> &constraints)
  {
    for (const auto &item : parse_spec_list(spec, where))
      {
        const auto names = split(item.name, '&');
        if (names.size() < 2)
          throw std::invalid_argument(where + ": '" + item.name +
                                      "' should name two or more boundaries joined by '&'");
        std::vector<bool> fixed(dim, false);
        for (const auto &f : item.fields)
          {
            const std::string c = f.key.empty() ? f.value : "";
            if (c == "x" || c == "y" || (c == "z" && dim == 3))
              fixed[c[0] - 'x'] = true;
            else
              throw std::invalid_argument(where + ": '" + item.name + "' lists '" + f.value +
                                          "'; expected components x, y" +
                                          (dim == 3 ? ", z" : ""));
          }
        if (item.fields.empty())
          throw std::invalid_argument(where + ": '" + item.name +
                                      "' names no component (e.g. 'bottom & sides: z')");

        auto common = boundary_dof_points(
          problem, boundary_id_of(names[0], problem.geometry.boundary_ids, where));
        for (unsigned int k = 1; k < names.size(); ++k)
          {
            const auto other = boundary_dof_points(
              problem, boundary_id_of(names[k], problem.geometry.boundary_ids, where));
            for (auto it = common.begin(); it != common.end();)
              it = other.count(it->first) ? std::next(it) : common.erase(it);
          }
        if (common.empty())
          throw std::invalid_argument(where + ": boundaries '" + item.name + "' do not meet");
        for (const auto &[dof, location] : common)
          if (fixed[location.component] && !constraints.is_constrained(dof))
            constraints.add_line(dof); // zero, no entries
      }
  }

  template void add_edge_supports<2>(const Discretization<2> &, const std::string &,
                                     const std::string &, dealii::AffineConstraints<double> &);
  template void add_edge_supports<3>(const Discretization<3> &, const std::string &,
                                     const std::string &, dealii::AffineConstraints<double> &);
} // namespace compliant
