#include "contact/contact_surface.h"

#include "discretization/face_nodes.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  template <int dim>
  ContactSurface<dim>::ContactSurface(const DoFHandler<dim> &dofs, const Mapping<dim> &mapping,
                                      const std::set<int> &ids, MPI_Comm communicator)
  {
    const auto &fe   = dofs.get_fe();
    const auto &base = fe.base_element(0);
    if (!fe.reference_cell().is_hyper_cube())
      throw std::invalid_argument("Contact/Pairs: contact between boundaries needs quadrilateral or hexahedral "
                                  "cells");
    const auto &unit = base.get_unit_support_points();
    for (const auto &p : unit)
      support.push_back(p[0]);
    std::sort(support.begin(), support.end());
    support.erase(std::unique(support.begin(), support.end(),
                              [](const double a, const double b) { return std::abs(a - b) < 1e-12; }),
                  support.end());
    const auto index_of = [&](const double t) {
      for (unsigned int a = 0; a < support.size(); ++a)
        if (std::abs(support[a] - t) < 1e-12)
          return a;
      throw std::logic_error("ContactSurface: a support point off the 1D points");
    };

    // Each face of an owned cell on the boundaries: orientation, then per node its DoFs,
    // reference position and 1D polynomial indices; all ranks' faces in rank order.
    FEValues<dim>       fe_values(mapping, fe, Quadrature<dim>(unit), update_quadrature_points);
    std::vector<double> local;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && ids.count(cell->face(f)->boundary_id()) > 0)
            {
              const auto nodes = face_nodes(cell, f, fe_values);
              const auto centre = cell->center();
              local.push_back(nodes.size());
              for (unsigned int d = 0; d < dim; ++d)
                local.push_back(centre[d]);
              for (const auto &[index, node] : nodes)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    local.push_back(node.dofs[d]), own_dofs.push_back(node.dofs[d]);
                  for (unsigned int d = 0; d < dim; ++d)
                    local.push_back(node.position[d]);
                  for (unsigned int d = 0; d < dim; ++d)
                    if (d != f / 2) // the face's own directions, in the cell's order
                      local.push_back(index_of(unit[index][d]));
                }
            }
    std::map<types::global_dof_index, unsigned int> by_first_dof;
    std::vector<Point<dim>>                         centres;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      for (std::size_t k = 0; k < part.size();)
        {
          Face               face;
          const unsigned int n = static_cast<unsigned int>(part[k++]);
          Point<dim>         centre;
          for (unsigned int d = 0; d < dim; ++d)
            centre[d] = part[k++];
          for (unsigned int i = 0; i < n; ++i)
            {
              Node node;
              for (unsigned int d = 0; d < dim; ++d)
                node.dofs[d] = static_cast<types::global_dof_index>(part[k++]);
              for (unsigned int d = 0; d < dim; ++d)
                node.reference[d] = part[k++];
              std::array<unsigned int, dim - 1> polynomial;
              for (unsigned int d = 0; d + 1 < dim; ++d)
                polynomial[d] = static_cast<unsigned int>(part[k++]);
              const auto [it, inserted] = by_first_dof.emplace(node.dofs[0], surface_nodes.size());
              if (inserted)
                surface_nodes.push_back(node);
              face.nodes.push_back(it->second);
              face.lagrange.push_back(polynomial);
            }
          surface_faces.push_back(face);
          centres.push_back(centre);
        }
    std::sort(own_dofs.begin(), own_dofs.end());
    own_dofs.erase(std::unique(own_dofs.begin(), own_dofs.end()), own_dofs.end());
    update({});
    // Outward: the normal of the parametrization points away from the cell's centre, or is turned.
    for (unsigned int f = 0; f < surface_faces.size(); ++f)
      {
        std::array<double, dim - 1>              middle;
        std::array<Tensor<1, dim>, dim - 1> tangents;
        middle.fill(0.5);
        const Point<dim> x = position(surface_faces[f], middle, &tangents);
        if (normal(surface_faces[f], tangents) * (x - centres[f]) < 0)
          surface_faces[f].orientation = -1;
      }
  }

  template <int dim>
  void ContactSurface<dim>::update(const std::map<types::global_dof_index, double> &displacement)
  {
    positions.resize(surface_nodes.size());
    for (unsigned int i = 0; i < surface_nodes.size(); ++i)
      {
        positions[i] = surface_nodes[i].reference;
        for (unsigned int d = 0; d < dim; ++d)
          if (const auto it = displacement.find(surface_nodes[i].dofs[d]); it != displacement.end())
            positions[i][d] += it->second;
      }
    boxes.resize(surface_faces.size());
    largest_face = 0;
    for (unsigned int f = 0; f < surface_faces.size(); ++f)
      {
        Point<dim> low = positions[surface_faces[f].nodes[0]], high = low;
        for (const unsigned int i : surface_faces[f].nodes)
          for (unsigned int d = 0; d < dim; ++d)
            low[d] = std::min(low[d], positions[i][d]), high[d] = std::max(high[d], positions[i][d]);
        boxes[f]     = {low, high};
        largest_face = std::max(largest_face, low.distance(high));
      }
  }

  template <int dim>
  double ContactSurface<dim>::lagrange(const unsigned int a, const double t, double *derivative) const
  {
    double value = 1, slope = 0;
    for (unsigned int b = 0; b < support.size(); ++b)
      if (b != a)
        {
          const double scale = 1. / (support[a] - support[b]);
          slope              = slope * (t - support[b]) * scale + value * scale;
          value *= (t - support[b]) * scale;
        }
    if (derivative)
      *derivative = slope;
    return value;
  }

  template <int dim>
  void ContactSurface<dim>::shape_values(const Face &face, const std::array<double, dim - 1> &xi,
                                         std::vector<double> &values) const
  {
    values.resize(face.nodes.size());
    for (unsigned int i = 0; i < face.nodes.size(); ++i)
      {
        values[i] = 1;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          values[i] *= lagrange(face.lagrange[i][d], xi[d], nullptr);
      }
  }

  template <int dim>
  Point<dim> ContactSurface<dim>::position(const Face &face, const std::array<double, dim - 1> &xi,
                                           std::array<Tensor<1, dim>, dim - 1> *tangents) const
  {
    Point<dim> x;
    if (tangents)
      for (auto &t : *tangents)
        t = Tensor<1, dim>();
    for (unsigned int i = 0; i < face.nodes.size(); ++i)
      {
        std::array<double, dim - 1> value, slope;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          value[d] = lagrange(face.lagrange[i][d], xi[d], &slope[d]);
        double n = 1;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          n *= value[d];
        const Point<dim> &p = positions[face.nodes[i]];
        x += n * p;
        if (tangents)
          for (unsigned int d = 0; d + 1 < dim; ++d)
            {
              double derivative = slope[d];
              for (unsigned int e = 0; e + 1 < dim; ++e)
                if (e != d)
                  derivative *= value[e];
              (*tangents)[d] += derivative * p;
            }
      }
    return x;
  }

  template <int dim>
  Tensor<1, dim> ContactSurface<dim>::normal(const Face &face, const std::array<Tensor<1, dim>, dim - 1> &t,
                                             double *area_element) const
  {
    Tensor<1, dim> n;
    if constexpr (dim == 2)
      n[0] = t[0][1], n[1] = -t[0][0];
    else
      n = cross_product_3d(t[0], t[1]);
    const double length = n.norm();
    if (area_element)
      *area_element = length;
    return length > 0 ? Tensor<1, dim>(face.orientation * n / length) : n;
  }

  template <int dim>
  bool ContactSurface<dim>::closest_on_face(const unsigned int face_index, const Point<dim> &x,
                                            std::array<double, dim - 1> &xi, const bool unbounded) const
  {
    // Gauss-Newton on |x(xi) - x|^2, kept near the face; inside if it ends within it.
    const Face &face = surface_faces[face_index];
    xi.fill(0.5);
    for (unsigned int iteration = 0; iteration < 30; ++iteration)
      {
        std::array<Tensor<1, dim>, dim - 1> t;
        const Tensor<1, dim>                r = position(face, xi, &t) - x;
        std::array<double, dim - 1>         step;
        if constexpr (dim == 2)
          step[0] = -(t[0] * r) / (t[0] * t[0]);
        else
          {
            const double a = t[0] * t[0], b = t[0] * t[1], c = t[1] * t[1], g0 = t[0] * r, g1 = t[1] * r;
            const double det = a * c - b * b;
            step[0]          = -(c * g0 - b * g1) / det;
            step[1]          = -(a * g1 - b * g0) / det;
          }
        double largest = 0;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          {
            xi[d]   = unbounded ? xi[d] + step[d] : std::clamp(xi[d] + step[d], -0.5, 1.5);
            largest = std::max(largest, std::abs(step[d]));
          }
        if (!(largest > 1e-14))
          break;
      }
    if (unbounded)
      return true;
    bool inside = true;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      {
        inside = inside && xi[d] >= -1e-10 && xi[d] <= 1 + 1e-10;
        xi[d]  = std::clamp(xi[d], 0., 1.);
      }
    return inside;
  }

  template <int dim>
  typename ContactSurface<dim>::Projection ContactSurface<dim>::project(const Point<dim> &x, const double reach,
                                                                               const Tensor<1, dim> *facing) const
  {
    Projection best;
    double     nearest = std::numeric_limits<double>::max();
    for (unsigned int f = 0; f < surface_faces.size(); ++f)
      {
        bool near = true;
        for (unsigned int d = 0; d < dim; ++d)
          near = near && x[d] >= boxes[f].first[d] - reach && x[d] <= boxes[f].second[d] + reach;
        std::array<double, dim - 1> xi;
        if (!near || !closest_on_face(f, x, xi))
          continue;
        std::array<Tensor<1, dim>, dim - 1> t;
        const Point<dim>                    on = position(surface_faces[f], xi, &t);
        const Tensor<1, dim>                n  = normal(surface_faces[f], t);
        if (facing && n * *facing >= 0)
          continue;
        if (x.distance(on) < nearest)
          {
            nearest       = x.distance(on);
            best.found    = true;
            best.face     = f;
            best.xi       = xi;
            best.on       = on;
            best.normal   = n;
            best.distance = (x - on) * best.normal;
          }
      }
    return best;
  }

  template <int dim>
  std::vector<unsigned int> ContactSurface<dim>::corners(const Face &face) const
  {
    const unsigned int last = support.size() - 1;
    std::vector<std::array<unsigned int, dim - 1>> wanted;
    if constexpr (dim == 2)
      wanted = {{0}, {last}};
    else
      wanted = {{0, 0}, {last, 0}, {last, last}, {0, last}};
    std::vector<unsigned int> result;
    for (const auto &w : wanted)
      for (unsigned int i = 0; i < face.nodes.size(); ++i)
        if (face.lagrange[i] == w)
          result.push_back(i);
    return result;
  }

  template class ContactSurface<2>;
  template class ContactSurface<3>;
} // namespace compliant
