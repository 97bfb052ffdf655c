// Named points of a Quantities entry ('tip: 48 60; mid: L/2 H'), coordinates as numbers or
// expressions of geometry parameters. Internal to solver/fe/quantities.
#pragma once

#include <deal.II/base/point.h>

#include "input/expression.h"
#include "input/spec_list.h"

#include <map>
#include <stdexcept>
#include <string>

namespace compliant
{
  template <int dim>
  std::map<std::string, dealii::Point<dim>>
  parse_named_points(const std::string &list, const std::map<std::string, double> &geometry_parameters,
                     const std::string &where)
  {
    std::map<std::string, dealii::Point<dim>> points;
    for (const auto &item : parse_spec_list(list, where))
      {
        if (item.fields.size() != 1 || !item.fields[0].key.empty())
          throw std::invalid_argument(where + ": expected 'name: x y [z]' for '" + item.name + "'");
        const auto x = evaluate_coordinates(item.fields[0].value, geometry_parameters,
                                            where + " '" + item.name + "'");
        if (x.size() != dim)
          throw std::invalid_argument(where + ": '" + item.name + "' needs " + std::to_string(dim) +
                                      " coordinates");
        for (unsigned int d = 0; d < dim; ++d)
          points[item.name][d] = x[d];
      }
    return points;
  }
} // namespace compliant
