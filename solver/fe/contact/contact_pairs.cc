#include "contact/contact_pairs.h"

#include "discretization/boundary_conditions.h"
#include "input/spec_list.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <iostream>
#include <cmath>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  std::vector<ContactPair> parse_contact_pairs(const std::string &spec, const std::map<std::string, int> &boundaries)
  {
    const std::string        where = "Contact/Pairs";
    std::vector<ContactPair> pairs;
    for (const auto &item : parse_spec_list(spec, where))
      {
        ContactPair pair;
        pair.name = item.name;
        for (const auto &other : pairs)
          if (other.name == pair.name)
            throw std::invalid_argument(where + ": pair '" + pair.name + "' given twice");
        for (const auto &f : item.fields)
          if (f.key != "slave" && f.key != "master")
            throw std::invalid_argument(where + ": pair '" + pair.name + "' takes slave=<boundaries> and "
                                        "master=<boundaries>, not '" + (f.key.empty() ? f.value : f.key) + "'");
        for (const std::string key : {"slave", "master"})
          {
            if (!item.has(key))
              throw std::invalid_argument(where + ": pair '" + pair.name + "' needs " + key + "=<boundaries>");
            std::string names = item.get(key);
            std::replace(names.begin(), names.end(), ',', ' ');
            auto &ids = key == "slave" ? pair.slave : pair.master;
            for (const auto &name : split(names, ' '))
              if (!name.empty())
                ids.insert(boundary_id_of(name, boundaries, where + " " + key + " of '" + pair.name + "'"));
            if (ids.empty())
              throw std::invalid_argument(where + ": pair '" + pair.name + "' needs " + key + "=<boundaries>");
          }
        for (const int id : pair.slave)
          if (pair.master.count(id))
            throw std::invalid_argument(where + ": pair '" + pair.name + "' names one boundary as both slave and "
                                        "master; a part touching itself needs two boundaries");
        // A boundary held by two pairs, or slave of one and master of another, would give
        // constraint lines that refer to each other (a cycle AffineConstraints cannot close).
        for (const auto &other : pairs)
          for (const int id : pair.slave)
            if (other.slave.count(id) || other.master.count(id))
              throw std::invalid_argument(where + ": pairs '" + other.name + "' and '" + pair.name +
                                          "' share a boundary that is a slave of one: a slave boundary may belong "
                                          "to one pair only, and never be another pair's master");
        for (const auto &other : pairs)
          for (const int id : pair.master)
            if (other.slave.count(id))
              throw std::invalid_argument(where + ": pairs '" + other.name + "' and '" + pair.name +
                                          "' share a boundary that is a slave of one: a slave boundary may belong "
                                          "to one pair only, and never be another pair's master");
        pairs.push_back(pair);
      }
    return pairs;
  }

  template <int dim>
  ContactPairs<dim>::ContactPairs(const std::vector<ContactPair> &pairs, const std::set<int> &excluded,
                                  const DoFHandler<dim> &dofs, const Mapping<dim> &mapping, const IndexSet &owned,
                                  const IndexSet &relevant, const double thickness, const double tolerance,
                                  MPI_Comm communicator)
    : contact_pairs(pairs)
    , owned_dofs(owned)
    , relevant_dofs(relevant)
    , thickness(thickness)
    , tolerance(tolerance)
    , communicator(communicator)
  {
    std::set<types::global_dof_index> left_out;
    if (!excluded.empty())
      for (const auto &node : ContactSurface<dim>(dofs, mapping, excluded, communicator).nodes())
        left_out.insert(node.dofs[0]);
    for (const auto &pair : pairs)
      {
        Side side;
        side.slave  = std::make_unique<ContactSurface<dim>>(dofs, mapping, pair.slave, communicator);
        side.master = std::make_unique<ContactSurface<dim>>(dofs, mapping, pair.master, communicator);
        if (side.slave->faces().empty() || side.master->faces().empty())
          throw std::invalid_argument("Contact/Pairs: pair '" + pair.name + "' has a boundary with no faces");
        std::set<types::global_dof_index> on_master;
        for (const auto &node : side.master->nodes())
          on_master.insert(node.dofs[0]);
        const unsigned int n = side.slave->nodes().size();
        side.candidate.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          {
            const auto first  = side.slave->nodes()[j].dofs[0];
            side.candidate[j] = on_master.count(first) == 0 && left_out.count(first) == 0;
          }
        side.active.assign(n, 0);
        integrate(side, true);
        side.area.resize(n);
        for (unsigned int j = 0; j < n; ++j)
          side.area[j] = side.mortar[j].weight * (dim == 2 ? thickness : 1.);
        sides.push_back(std::move(side));
      }
  }

  template <int dim>
  void ContactPairs<dim>::refresh(const PETScWrappers::MPI::Vector &u)
  {
    std::vector<double> local; // dof, value
    for (const auto &side : sides)
      for (const auto *surface : {side.slave.get(), side.master.get()})
        for (const auto dof : surface->local_dofs())
          local.push_back(dof), local.push_back(u(dof));
    std::map<types::global_dof_index, double> displacement;
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      for (std::size_t k = 0; k + 1 < part.size(); k += 2)
        displacement[static_cast<types::global_dof_index>(part[k])] = part[k + 1];
    // The mortar integrals depend on the surfaces' positions alone: at the state of the last
    // refresh (a Newton iteration's update and both constraint sets, then the output's calls)
    // they are kept. Every rank gathers the same map, so every rank decides alike.
    if (refreshed && displacement == refreshed_at)
      return;
    for (auto &side : sides)
      {
        side.slave->update(displacement);
        side.master->update(displacement);
        integrate(side, false);
      }
    refreshed_at = std::move(displacement);
    refreshed    = true;
  }

  namespace
  {
    using Parameters2 = std::array<double, 2>;

    // Sutherland-Hodgman: the part of a polygon (face parameters) inside the unit square.
    std::vector<Parameters2> clip_to_unit_square(std::vector<Parameters2> polygon)
    {
      for (unsigned int edge = 0; edge < 4 && !polygon.empty(); ++edge)
        {
          const unsigned int axis = edge % 2;
          const double       bound = edge < 2 ? 0. : 1., sign = edge < 2 ? 1. : -1.;
          const auto inside = [&](const Parameters2 &p) { return sign * (p[axis] - bound) >= 0; };
          std::vector<Parameters2> kept;
          for (unsigned int i = 0; i < polygon.size(); ++i)
            {
              const auto &a = polygon[i], &b = polygon[(i + 1) % polygon.size()];
              if (inside(a))
                kept.push_back(a);
              if (inside(a) != inside(b))
                {
                  const double t = (bound - a[axis]) / (b[axis] - a[axis]);
                  kept.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
                }
            }
          polygon = kept;
        }
      return polygon;
    }

    // Points and weights of a rule exact for polynomials of the given order per direction on the
    // parameter region: an interval (2D faces) or a triangle fan of a convex polygon (3D faces,
    // each triangle by the collapsed, Duffy, map of a square).
    template <int dim>
    void region_rule(const std::vector<std::array<double, dim - 1>> &region, const unsigned int n_gauss,
                     std::vector<std::array<double, dim - 1>> &points, std::vector<double> &weights)
    {
      const QGauss<1> gauss(n_gauss);
      points.clear(), weights.clear();
      if constexpr (dim == 2)
        {
          const double a = region[0][0], b = region[1][0];
          for (unsigned int q = 0; q < gauss.size(); ++q)
            points.push_back({a + (b - a) * gauss.point(q)[0]}), weights.push_back((b - a) * gauss.weight(q));
        }
      else
        for (unsigned int t = 1; t + 1 < region.size(); ++t)
          {
            const auto  &A = region[0], &B = region[t], &C = region[t + 1];
            const double twice_area = std::abs((B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]));
            for (unsigned int i = 0; i < gauss.size(); ++i)
              for (unsigned int j = 0; j < gauss.size(); ++j)
                {
                  const double u = gauss.point(i)[0], v = gauss.point(j)[0];
                  points.push_back({A[0] + u * (B[0] - A[0] + v * (C[0] - B[0])),
                                    A[1] + u * (B[1] - A[1] + v * (C[1] - B[1]))});
                  weights.push_back(gauss.weight(i) * gauss.weight(j) * u * twice_area);
                }
          }
    }

    // The dual basis psi_i = sum_l A_il N_l of a slave face, A = D M^-1 (M the face's mass
    // matrix, D its row sums): int psi_i N_l = delta_il int N_i, so a node's weighted gap moves
    // with that node alone, and sum_i psi_i = 1 (Wohlmuth 2000; Popp et al. 2010).
    template <int dim>
    FullMatrix<double> dual_basis(const ContactSurface<dim> &slave, const typename ContactSurface<dim>::Face &face,
                                  const unsigned int n_gauss)
    {
      const unsigned int                       n = face.nodes.size();
      FullMatrix<double>                       mass(n, n), dual(n, n);
      std::vector<std::array<double, dim - 1>> full, points;
      std::vector<double>                      weights, values;
      if constexpr (dim == 2)
        full = {{0.}, {1.}};
      else
        full = {{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}};
      region_rule<dim>(full, n_gauss, points, weights);
      std::array<Tensor<1, dim>, dim - 1> t;
      for (unsigned int q = 0; q < points.size(); ++q)
        {
          slave.position(face, points[q], &t);
          double area_element;
          slave.normal(face, t, &area_element);
          slave.shape_values(face, points[q], values);
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int l = 0; l < n; ++l)
              mass(i, l) += values[i] * values[l] * weights[q] * area_element;
        }
      dual.invert(mass);
      for (unsigned int i = 0; i < n; ++i)
        {
          double row_sum = 0;
          for (unsigned int l = 0; l < n; ++l)
            row_sum += mass(i, l);
          for (unsigned int l = 0; l < n; ++l)
            dual(i, l) *= row_sum;
        }
      return dual;
    }

    template <int dim>
    bool boxes_meet(const std::pair<Point<dim>, Point<dim>> &a, const std::pair<Point<dim>, Point<dim>> &b,
                    const double reach)
    {
      for (unsigned int d = 0; d < dim; ++d)
        if (a.second[d] + reach < b.first[d] || b.second[d] + reach < a.first[d])
          return false;
      return true;
    }
  } // namespace

  template <int dim>
  void ContactPairs<dim>::integrate(Side &side, const bool at_rest) const
  {
    // at_rest: the slave surface's nodal areas int N_j dA over all of it (master or not).
    // Otherwise each slave face meets the master faces facing it: the part of it each covers
    // (the master face's corners projected onto the slave face's parameters, clipped to it) is
    // integrated with the master face known, exactly for flat faces.
    const auto &slave = *side.slave, &master = *side.master;
    side.mortar.assign(slave.nodes().size(), Mortar());
    std::vector<std::map<unsigned int, double>> weights(slave.nodes().size());
    const double reach = std::max(slave.face_size(), master.face_size());
    std::vector<double>                      n_slave, n_master, rule_weights;
    std::vector<std::array<double, dim - 1>> rule_points;
    std::array<double, dim - 1>              middle;
    middle.fill(0.5);
    for (unsigned int f = 0; f < slave.faces().size(); ++f)
      {
        const auto &face = slave.faces()[f];
        if (std::none_of(face.nodes.begin(), face.nodes.end(),
                         [&](const unsigned int j) { return relevant(slave.nodes()[j]); }))
          continue;
        const unsigned int per_direction =
          static_cast<unsigned int>(std::round(std::pow(face.nodes.size(), 1. / (dim - 1))));
        const unsigned int n_gauss = 2 * per_direction + 1;
        std::array<Tensor<1, dim>, dim - 1> t;
        slave.position(face, middle, &t);
        const Tensor<1, dim> face_normal = slave.normal(face, t);
        const FullMatrix<double> dual = at_rest ? FullMatrix<double>() : dual_basis(slave, face, n_gauss);
        // (master face, region of this face's parameters) pairs
        std::vector<std::pair<int, std::vector<std::array<double, dim - 1>>>> regions;
        if (at_rest)
          {
            if constexpr (dim == 2)
              regions.push_back({-1, {{0.}, {1.}}});
            else
              regions.push_back({-1, {{0., 0.}, {1., 0.}, {1., 1.}, {0., 1.}}});
          }
        else
          for (unsigned int g = 0; g < master.faces().size(); ++g)
            {
              const auto &mface = master.faces()[g];
              if (!boxes_meet<dim>(slave.box(f), master.box(g), reach))
                continue;
              master.position(mface, middle, &t);
              if (master.normal(mface, t) * face_normal >= 0)
                continue; // the two sides of a contact face each other
              std::vector<std::array<double, dim - 1>> corners;
              for (const unsigned int i : master.corners(mface))
                {
                  std::array<double, dim - 1> xi;
                  slave.closest_on_face(f, master.current(mface.nodes[i]), xi, true);
                  corners.push_back(xi);
                }
              if constexpr (dim == 2)
                {
                  const double a = std::max(0., std::min(corners[0][0], corners[1][0]));
                  const double b = std::min(1., std::max(corners[0][0], corners[1][0]));
                  if (b - a > 1e-12)
                    regions.push_back({static_cast<int>(g), {{a}, {b}}});
                }
              else
                {
                  const auto clipped = clip_to_unit_square(corners);
                  if (clipped.size() >= 3)
                    regions.push_back({static_cast<int>(g), clipped});
                }
            }
        for (const auto &[g, region] : regions)
          {
            region_rule<dim>(region, n_gauss, rule_points, rule_weights);
            for (unsigned int q = 0; q < rule_points.size(); ++q)
              {
                const Point<dim> x = slave.position(face, rule_points[q], &t);
                double           area_element;
                slave.normal(face, t, &area_element);
                const double w = rule_weights[q] * area_element;
                slave.shape_values(face, rule_points[q], n_slave);
                if (g < 0)
                  {
                    for (unsigned int i = 0; i < face.nodes.size(); ++i)
                      side.mortar[face.nodes[i]].weight += n_slave[i] * w;
                    continue;
                  }
                const auto                 &mface = master.faces()[g];
                std::array<double, dim - 1> xi_m;
                master.closest_on_face(g, x, xi_m);
                std::array<Tensor<1, dim>, dim - 1> tm;
                const Point<dim>                    y = master.position(mface, xi_m, &tm);
                const Tensor<1, dim>                n = master.normal(mface, tm);
                const double                        distance = (x - y) * n;
                master.shape_values(mface, xi_m, n_master);
                for (unsigned int i = 0; i < face.nodes.size(); ++i)
                  {
                    auto  &m  = side.mortar[face.nodes[i]];
                    double nw = 0; // psi_i w
                    for (unsigned int l = 0; l < face.nodes.size(); ++l)
                      nw += dual(i, l) * n_slave[l] * w;
                    m.weight += nw;
                    m.gap += nw * distance;
                    m.normal += nw * n;
                    for (unsigned int k = 0; k < n_master.size(); ++k)
                      weights[face.nodes[i]][mface.nodes[k]] += nw * n_master[k];
                  }
              }
          }
      }
    if (at_rest)
      return;
    for (unsigned int j = 0; j < side.mortar.size(); ++j)
      {
        auto &m = side.mortar[j];
        // A node whose dual function meets the master only where it is small or negative (at the
        // edge of the contact zone) does not hold: its weighted gap would mean nothing.
        if (!(m.weight > 0.25 * side.area[j] / (dim == 2 ? thickness : 1.)) || m.normal.norm() == 0)
          {
            m.weight = 0;
            continue;
          }
        m.gap /= m.weight;
        m.normal /= m.normal.norm();
        for (const auto &[k, value] : weights[j])
          m.masters.emplace_back(k, value / m.weight);
      }
  }

  template <int dim>
  double ContactPairs<dim>::force_of(const Side &side, const unsigned int j, const PETScWrappers::MPI::Vector &residual) const
  {
    double lambda = 0;
    for (unsigned int d = 0; d < dim; ++d)
      lambda -= residual(side.slave->nodes()[j].dofs[d]) * side.mortar[j].normal[d];
    return lambda;
  }

  template <int dim>
  void ContactPairs<dim>::update_active_set(const PETScWrappers::MPI::Vector &u, const PETScWrappers::MPI::Vector &residual,
                                            const bool release, const double force_tolerance, unsigned int &changes,
                                            unsigned int &closed, unsigned int &pulling, double &violation)
  {
    refresh(u);
    unsigned int local_changes = 0, local_closed = 0, local_pulling = 0;
    double       local_violation = 0;
    for (auto &side : sides)
      {
        std::vector<int> decided(side.active.size(), 0);
        for (unsigned int j = 0; j < side.active.size(); ++j)
          {
            const auto &node = side.slave->nodes()[j];
            const auto &m    = side.mortar[j];
            if (!owned(node))
              continue;
            int now = 0;
            if (side.candidate[j] && m.weight > 0)
              {
                if (side.active[j])
                  {
                    // A force within Newton's tolerance of zero is no pull (ContactSet).
                    const bool pulls = force_of(side, j, residual) < -force_tolerance;
                    local_pulling += pulls;
                    now = pulls && release ? 0 : 1;
                  }
                else
                  now = m.gap < -tolerance ? 1 : 0;
                local_violation = std::max(local_violation, now ? std::abs(m.gap) : -m.gap);
              }
            if (now != side.active[j] && std::getenv("COMPLIANT_DEBUG_NEWTON"))
              std::cout << "    pair node " << j << " at " << side.slave->current(j) << " DoFs " << node.dofs[0] << " "
                        << node.dofs[1] << (now ? " held" : " freed") << ", force " << force_of(side, j, residual)
                        << ", gap " << m.gap << std::endl;
            local_changes += now != side.active[j];
            local_closed += !side.active[j] && now;
            decided[j] = now;
          }
        // The owners' decisions to every rank (each slave node has one owner).
        MPI_Allreduce(decided.data(), side.active.data(), static_cast<int>(decided.size()), MPI_INT, MPI_SUM,
                      communicator);
      }
    changes += Utilities::MPI::sum(local_changes, communicator);
    closed += Utilities::MPI::sum(local_closed, communicator);
    pulling += Utilities::MPI::sum(local_pulling, communicator);
    violation = std::max(violation, Utilities::MPI::max(local_violation, communicator));
  }

  template <int dim>
  void ContactPairs<dim>::add_constraints(AffineConstraints<double> &constraints, const PETScWrappers::MPI::Vector &u,
                                          const bool homogeneous)
  {
    refresh(u);
    for (const auto &side : sides)
      for (unsigned int j = 0; j < side.active.size(); ++j)
        {
          const auto &node = side.slave->nodes()[j];
          const auto &m    = side.mortar[j];
          if (!side.active[j] || !(m.weight > 0) || !relevant(node))
            continue;
          const Tensor<1, dim> &n = m.normal;
          int                   k = -1; // the free component most aligned with n
          for (unsigned int d = 0; d < dim; ++d)
            if (!constraints.is_constrained(node.dofs[d]) && (k < 0 || std::abs(n[d]) > std::abs(n[k])))
              k = d;
          if (k < 0 || std::abs(n[k]) < 0.2)
            continue;
          // A node already held by a line with entries (an obstacle's) would close a cycle.
          bool tied = false;
          for (unsigned int d = 0; d < dim; ++d)
            if (const auto *entries = constraints.get_constraint_entries(node.dofs[d]); entries && !entries->empty())
              tied = true;
          if (tied)
            continue;
          const auto line = node.dofs[k];
          constraints.add_line(line);
          for (unsigned int d = 0; d < dim; ++d)
            if (static_cast<int>(d) != k && n[d] != 0)
              constraints.add_entry(line, node.dofs[d], -n[d] / n[k]);
          for (const auto &[master, share] : m.masters)
            for (unsigned int d = 0; d < dim; ++d)
              if (n[d] != 0 && share != 0)
                constraints.add_entry(line, side.master->nodes()[master].dofs[d], share * n[d] / n[k]);
          constraints.set_inhomogeneity(line, homogeneous ? 0. : -m.gap / n[k]);
        }
  }

  template <int dim>
  std::vector<typename ContactPairs<dim>::PairResult>
  ContactPairs<dim>::result(const PETScWrappers::MPI::Vector &u, const PETScWrappers::MPI::Vector &residual,
                            double &max_penetration)
  {
    refresh(u);
    std::vector<PairResult> results(sides.size());
    double                  deepest = 0;
    for (unsigned int s = 0; s < sides.size(); ++s)
      {
        const auto &side = sides[s];
        auto       &r    = results[s];
        for (unsigned int j = 0; j < side.active.size(); ++j)
          {
            const auto &node = side.slave->nodes()[j];
            if (!owned(node) || !side.candidate[j] || !(side.mortar[j].weight > 0))
              continue;
            deepest = std::max(deepest, -side.mortar[j].gap);
            if (!side.active[j])
              continue;
            const Tensor<1, dim> f = force_of(side, j, residual) * side.mortar[j].normal;
            r.force += f;
            Tensor<1, 3>      x3, f3;
            const Point<dim> &x = side.slave->current(j);
            for (unsigned int d = 0; d < dim; ++d)
              x3[d] = x[d], f3[d] = f[d];
            r.moment += cross_product_3d(x3, f3);
            ++r.nodes;
          }
        r.force  = Utilities::MPI::sum(r.force, communicator);
        r.moment = Utilities::MPI::sum(r.moment, communicator);
        r.nodes  = Utilities::MPI::sum(r.nodes, communicator);
      }
    max_penetration = std::max(max_penetration, Utilities::MPI::max(deepest, communicator));
    return results;
  }

  template <int dim>
  void ContactPairs<dim>::append_rows(const PETScWrappers::MPI::Vector &u, const PETScWrappers::MPI::Vector &residual,
                                      const double first_index, std::vector<double> &rows)
  {
    refresh(u);
    for (unsigned int s = 0; s < sides.size(); ++s)
      for (unsigned int j = 0; j < sides[s].active.size(); ++j)
        {
          const auto &side = sides[s];
          const auto &node = side.slave->nodes()[j];
          if (!owned(node) || !side.candidate[j])
            continue;
          const double force = side.active[j] ? force_of(side, j, residual) : 0.;
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(node.reference[d]);
          for (unsigned int d = 0; d < dim; ++d)
            rows.push_back(side.slave->current(j)[d]);
          const double gap = side.mortar[j].weight > 0 ? side.mortar[j].gap : std::nan("");
          rows.insert(rows.end(), {gap, force, side.area[j], side.area[j] > 0 ? force / side.area[j] : 0.,
                                   side.active[j] ? first_index + s : -1.});
        }
  }

  template <int dim>
  void ContactPairs<dim>::nodal_fields(const PETScWrappers::MPI::Vector &u, const PETScWrappers::MPI::Vector &residual,
                                       PETScWrappers::MPI::Vector &pressure, PETScWrappers::MPI::Vector &gap)
  {
    refresh(u);
    for (const auto &side : sides)
      for (unsigned int j = 0; j < side.active.size(); ++j)
        {
          const auto &node = side.slave->nodes()[j];
          if (!owned(node) || !side.candidate[j])
            continue;
          const double force     = side.active[j] ? force_of(side, j, residual) : 0.;
          pressure(node.dofs[0]) = side.area[j] > 0 ? force / side.area[j] : 0.;
          gap(node.dofs[0])      = side.mortar[j].weight > 0 ? side.mortar[j].gap : 0.;
        }
  }

  template <int dim>
  void ContactPairs<dim>::release_all()
  {
    for (auto &side : sides)
      std::fill(side.active.begin(), side.active.end(), 0);
  }

  template class ContactPairs<2>;
  template class ContactPairs<3>;
} // namespace compliant
