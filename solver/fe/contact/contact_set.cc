#include "contact/contact_set.h"

#include "discretization/face_nodes.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <map>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // The part's size: the diagonal of the bounding box of all vertices.
    template <int dim>
    double part_size(const Triangulation<dim> &triangulation, MPI_Comm communicator)
    {
      std::vector<double> low(dim, std::numeric_limits<double>::max()), high(dim, -std::numeric_limits<double>::max());
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto v : cell->vertex_indices())
            for (unsigned int d = 0; d < dim; ++d)
              {
                low[d]  = std::min(low[d], cell->vertex(v)[d]);
                high[d] = std::max(high[d], cell->vertex(v)[d]);
              }
      double squared = 0;
      for (unsigned int d = 0; d < dim; ++d)
        squared += std::pow(Utilities::MPI::max(high[d], communicator) - Utilities::MPI::min(low[d], communicator), 2);
      return std::sqrt(squared);
    }
  } // namespace

  template <int dim>
  ContactSet<dim>::ContactSet(std::vector<Obstacle<dim>> obstacles_in, const std::set<int> &excluded,
                              const std::set<int> &supported,
                              const DoFHandler<dim> &dofs, const Mapping<dim> &mapping,
                              const Quadrature<dim - 1> &face_quadrature, const IndexSet &owned,
                              const IndexSet &relevant, const double thickness, const double relative_tolerance,
                              MPI_Comm communicator)
    : obstacles(std::move(obstacles_in))
    , communicator(communicator)
    , owned_dofs(owned)
    , relevant_dofs(relevant)
  {
    tolerance = relative_tolerance * part_size(dofs.get_triangulation(), communicator);
    const auto           &fe   = dofs.get_fe();
    const auto           &base = fe.base_element(0); // the displacement's FE_Q
    const Quadrature<dim> support(base.get_unit_support_points());
    FEValues<dim>         fe_values(mapping, fe, support, update_quadrature_points);
    FEFaceValues<dim>     face_values(mapping, fe, face_quadrature, update_values | update_JxW_values);
    std::vector<types::global_dof_index> cell_dofs(fe.n_dofs_per_cell());
    std::map<types::global_dof_index, Node> by_dof; // by the node's x DoF
    std::set<types::global_dof_index>       left_out, held;
    PETScWrappers::MPI::Vector              area(owned, communicator);
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned() || cell->is_ghost())
        for (const auto f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const int          id = cell->face(f)->boundary_id();
            std::vector<bool>  allowed(obstacles.size());
            for (unsigned int o = 0; o < obstacles.size(); ++o)
              allowed[o] = obstacles[o].boundary_ids.count(id) > 0;
            const bool is_excluded = excluded.count(id) > 0, is_supported = supported.count(id) > 0;
            const bool touches     = std::find(allowed.begin(), allowed.end(), true) != allowed.end();
            if (!is_excluded && !is_supported && !touches)
              continue;
            for (const auto &[index, face_node] : face_nodes(cell, f, fe_values))
              {
                const Node node{face_node.dofs, face_node.position, allowed};
                if (is_excluded)
                  left_out.insert(node.dofs[0]);
                if (is_supported)
                  held.insert(node.dofs[0]);
                auto [it, inserted] = by_dof.emplace(node.dofs[0], node);
                if (!inserted)
                  for (unsigned int o = 0; o < obstacles.size(); ++o)
                    it->second.allowed[o] = it->second.allowed[o] || node.allowed[o];
              }
            // The lumped area of each node: the integral of its shape function over the face.
            if (cell->is_locally_owned() && !is_excluded && touches)
              {
                cell->get_dof_indices(cell_dofs);
                face_values.reinit(cell, f);
                for (unsigned int i = 0; i < cell_dofs.size(); ++i)
                  if (fe.system_to_base_index(i).first == std::make_pair(0u, 0u))
                    {
                      double integral = 0;
                      for (unsigned int q = 0; q < face_quadrature.size(); ++q)
                        integral += face_values.shape_value_component(i, q, 0) * face_values.JxW(q);
                      if (integral != 0)
                        area(cell_dofs[i]) += thickness * integral;
                    }
              }
          }
    area.compress(VectorOperation::add);
    PETScWrappers::MPI::Vector ghosted_area(owned, relevant, communicator);
    ghosted_area = area;
    for (const auto &[first, node] : by_dof)
      if (left_out.count(first) == 0 && std::find(node.allowed.begin(), node.allowed.end(), true) != node.allowed.end())
        {
          Node n      = node;
          n.owned     = owned.is_element(first);
          n.supported = held.count(first) > 0;
          n.area  = ghosted_area(first);
          nodes.push_back(n);
        }

    // The active set starts from the part at rest: a node already inside an obstacle there is held
    // onto its surface in one jump, which inverts the cells beside it (Newton fails at every step
    // size). An obstacle drawn into the part is an input error; say where.
    struct
    {
      double depth;
      int    rank;
    } deepest{0., static_cast<int>(Utilities::MPI::this_mpi_process(communicator))};
    std::vector<double> where(dim + 1, 0.);
    for (const auto &node : nodes)
      if (node.owned)
        {
          double         gap;
          Tensor<1, dim> n;
          const auto     o = nearest(node, node.reference, 0, gap, n);
          if (-gap > deepest.depth)
            {
              deepest.depth = -gap;
              for (unsigned int d = 0; d < dim; ++d)
                where[d] = node.reference[d];
              where[dim] = o;
            }
        }
    MPI_Allreduce(MPI_IN_PLACE, &deepest, 1, MPI_DOUBLE_INT, MPI_MAXLOC, communicator);
    if (deepest.depth <= tolerance)
      return;
    where = Utilities::MPI::broadcast(communicator, where, deepest.rank);
    std::ostringstream message;
    message << "Contact/Obstacles: obstacle '" << obstacles[static_cast<unsigned>(where[dim])].name
            << "' overlaps the part at rest: the contact boundary's node at (";
    for (unsigned int d = 0; d < dim; ++d)
      message << (d ? ", " : "") << where[d];
    message << ") lies " << deepest.depth << " inside it (tolerance " << tolerance
            << "); place the obstacle clear of the part or touching it";
    throw std::invalid_argument(message.str());
  }

  template <int dim>
  Point<dim> ContactSet<dim>::position(const Node &node, const PETScWrappers::MPI::Vector &u) const
  {
    Point<dim> x = node.reference;
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += u(node.dofs[d]);
    return x;
  }

  template <int dim>
  unsigned int ContactSet<dim>::nearest(const Node &node, const Point<dim> &x, const double load_factor, double &gap,
                                        Tensor<1, dim> &normal) const
  {
    unsigned int best = 0;
    gap               = std::numeric_limits<double>::max();
    for (unsigned int o = 0; o < obstacles.size(); ++o)
      if (node.allowed[o])
        {
          Tensor<1, dim> n;
          const double   g = obstacles[o].gap(x, load_factor, n);
          if (g < gap)
            gap = g, normal = n, best = o;
        }
    return best;
  }

  template <int dim>
  typename ContactSet<dim>::Update ContactSet<dim>::update_active_set(const PETScWrappers::MPI::Vector &u,
                                                                     const PETScWrappers::MPI::Vector &residual,
                                                                     const double load_factor, const bool release,
                                                                     const double force_tolerance)
  {
    Update update;
    for (auto &node : nodes)
      if (node.owned)
        {
          const Point<dim> x = position(node, u);
          Tensor<1, dim>   n;
          double           gap;
          int              now = -1;
          if (node.active >= 0)
            {
              gap           = obstacles[node.active].gap(x, load_factor, n);
              double lambda = 0;
              for (unsigned int d = 0; d < dim; ++d)
                lambda -= residual(node.dofs[d]) * n[d];
              // A force within Newton's tolerance of zero is no pull (a leaf lying on a former
              // without pressing on it): freeing such nodes on round-off made the set cycle.
              const bool pulls = lambda < -force_tolerance;
              update.pulling += pulls;
              now = pulls && release ? -1 : node.active;
              if (now >= 0 && !node.supported && obstacles[now].friction > 0)
                update_friction(node, x, gap, n, residual, load_factor, release, force_tolerance, update);
            }
          else
            {
              const unsigned int o = nearest(node, x, load_factor, gap, n);
              now                  = gap < -tolerance ? static_cast<int>(o) : -1;
              // A node sticking at the step's start and freed by a Newton iterate on its way
              // keeps that anchor if it lands on the same obstacle (it did not land elsewhere);
              // any other node that lands in the step sticks where it lands.
              if (now >= 0 && !(node.step_anchor && !node.slip && node.anchor_obstacle == now))
                stick_at(node, x, gap, n, load_factor);
            }
          update.changes += now != node.active;
          update.closed += node.active < 0 && now >= 0;
          update.violation = std::max(update.violation, now >= 0 ? std::abs(gap) : -gap);
          node.active      = now;
          if (now >= 0 && node.anchor_obstacle < 0)
            node.anchor_obstacle = now;
        }
    update.changes   = Utilities::MPI::sum(update.changes, communicator);
    update.closed    = Utilities::MPI::sum(update.closed, communicator);
    update.pulling   = Utilities::MPI::sum(update.pulling, communicator);
    update.violation = Utilities::MPI::max(update.violation, communicator);
    share_active_set();
    if (pairs)
      pairs->update_active_set(u, residual, release, force_tolerance, update.changes, update.closed, update.pulling,
                               update.violation);
    return update;
  }

  template <int dim>
  void ContactSet<dim>::share_active_set()
  {
    // Status at the node's first DoF: 0 free, +-(obstacle + 1) held (negative: slipping); with
    // friction the anchor at the node's DoFs and its load factor at the first.
    const bool                 friction = has_friction();
    PETScWrappers::MPI::Vector status(owned_dofs, communicator), anchor, anchor_load;
    if (friction)
      anchor.reinit(owned_dofs, communicator), anchor_load.reinit(owned_dofs, communicator);
    for (const auto &node : nodes)
      if (node.owned)
        {
          status(node.dofs[0]) = (node.active + 1) * (node.slip ? -1 : 1);
          if (friction)
            {
              for (unsigned int d = 0; d < dim; ++d)
                anchor(node.dofs[d]) = node.anchor[d];
              anchor_load(node.dofs[0]) = node.anchor_load;
            }
        }
    status.compress(VectorOperation::insert);
    PETScWrappers::MPI::Vector ghosted(owned_dofs, relevant_dofs, communicator), ghosted_anchor, ghosted_load;
    ghosted = status;
    if (friction)
      {
        anchor.compress(VectorOperation::insert);
        anchor_load.compress(VectorOperation::insert);
        ghosted_anchor.reinit(owned_dofs, relevant_dofs, communicator);
        ghosted_load.reinit(owned_dofs, relevant_dofs, communicator);
        ghosted_anchor = anchor;
        ghosted_load   = anchor_load;
      }
    for (auto &node : nodes)
      if (!node.owned)
        {
          const long code = std::lround(ghosted(node.dofs[0]));
          node.active     = static_cast<int>(std::abs(code)) - 1;
          node.slip       = code < 0;
          if (friction)
            {
              for (unsigned int d = 0; d < dim; ++d)
                node.anchor[d] = ghosted_anchor(node.dofs[d]);
              node.anchor_load = ghosted_load(node.dofs[0]);
            }
        }
  }

  template <int dim>
  void ContactSet<dim>::add_constraints(AffineConstraints<double> &constraints, const PETScWrappers::MPI::Vector &u,
                                        const double load_factor, const bool homogeneous) const
  {
    for (const auto &node : nodes)
      if (frictional(node) && !node.slip)
        {
          // Sticking: held at its anchor in every free component.
          const Point<dim> x = position(node, u), target = stick_target(node, load_factor);
          for (unsigned int d = 0; d < dim; ++d)
            if (!constraints.is_constrained(node.dofs[d]))
              {
                constraints.add_line(node.dofs[d]);
                constraints.set_inhomogeneity(node.dofs[d], homogeneous ? 0. : target[d] - x[d]);
              }
        }
      else if (node.active >= 0)
        {
          Tensor<1, dim> n;
          const double   gap = obstacles[node.active].gap(position(node, u), load_factor, n);
          // The component that carries the constraint: the free one most aligned with n.
          int k = -1;
          for (unsigned int d = 0; d < dim; ++d)
            if (!constraints.is_constrained(node.dofs[d]) && (k < 0 || std::abs(n[d]) > std::abs(n[k])))
              k = d;
          // Held components cannot move the node along n: it stays as the supports hold it.
          if (k < 0 || std::abs(n[k]) < 0.2)
            continue;
          constraints.add_line(node.dofs[k]);
          for (unsigned int d = 0; d < dim; ++d)
            if (static_cast<int>(d) != k && n[d] != 0)
              constraints.add_entry(node.dofs[k], node.dofs[d], -n[d] / n[k]);
          constraints.set_inhomogeneity(node.dofs[k], homogeneous ? 0. : -gap / n[k]);
        }
    if (pairs)
      pairs->add_constraints(constraints, u, homogeneous);
  }

  template <int dim>
  void ContactSet<dim>::require_fixed_frictionless(const std::string &what) const
  {
    for (const auto &o : obstacles)
      {
        if (o.motion.norm() > 0)
          throw std::invalid_argument("Contact/Obstacles: obstacle '" + o.name + "' moves (motion=); " + what +
                                      ", and a motion proportional to it would drive the path: hold the "
                                      "obstacle still and load the part, or use Path = load steps");
        if (o.friction > 0)
          throw std::invalid_argument("Contact/Obstacles: obstacle '" + o.name + "' has friction (friction=); " +
                                      what + ", and friction depends on the path taken: use Path = load steps");
      }
  }

  template <int dim>
  std::vector<std::string> ContactSet<dim>::names() const
  {
    std::vector<std::string> all;
    for (const auto &o : obstacles)
      all.push_back(o.name);
    if (pairs)
      for (const auto &p : pairs->pairs())
        all.push_back(p.name);
    return all;
  }

  template <int dim>
  typename ContactSet<dim>::Result ContactSet<dim>::result(const PETScWrappers::MPI::Vector &u,
                                                           const PETScWrappers::MPI::Vector &residual,
                                                           const double load_factor) const
  {
    Result result;
    result.obstacles.resize(obstacles.size());
    for (const auto &node : nodes)
      if (node.owned)
        {
          const auto state       = state_of(node, u, residual, load_factor);
          result.max_penetration = std::max(result.max_penetration, -state.nearest_gap);
          if (node.active < 0)
            continue;
          auto                &r = result.obstacles[node.active];
          const Tensor<1, dim> f = contact_force(node, state.normal, state.force, residual);
          r.force += f;
          Tensor<1, 3> x3, f3;
          for (unsigned int d = 0; d < dim; ++d)
            x3[d] = state.x[d], f3[d] = f[d];
          r.moment += cross_product_3d(x3, f3);
          ++r.nodes;
          if (frictional(node))
            ++(node.slip ? r.slipping : r.sticking);
          ++result.active_nodes;
        }
    for (auto &r : result.obstacles)
      {
        r.force  = Utilities::MPI::sum(r.force, communicator);
        r.moment = Utilities::MPI::sum(r.moment, communicator);
        r.nodes  = Utilities::MPI::sum(r.nodes, communicator);
        r.sticking = Utilities::MPI::sum(r.sticking, communicator);
        r.slipping = Utilities::MPI::sum(r.slipping, communicator);
      }
    result.active_nodes    = Utilities::MPI::sum(result.active_nodes, communicator);
    result.max_penetration = std::max(0., Utilities::MPI::max(result.max_penetration, communicator));
    if (pairs)
      for (const auto &pair : pairs->result(u, residual, result.max_penetration))
        {
          ObstacleResult r;
          r.force  = pair.force;
          r.moment = pair.moment;
          r.nodes  = pair.nodes;
          result.active_nodes += pair.nodes;
          result.obstacles.push_back(r);
        }
    return result;
  }

  template <int dim>
  void ContactSet<dim>::nodal_fields(const PETScWrappers::MPI::Vector &u, const PETScWrappers::MPI::Vector &residual,
                                     const double load_factor, PETScWrappers::MPI::Vector &pressure,
                                     PETScWrappers::MPI::Vector &gap) const
  {
    for (const auto &node : nodes)
      if (node.owned)
        {
          const auto state       = state_of(node, u, residual, load_factor);
          pressure(node.dofs[0]) = node.area > 0 ? state.force / node.area : 0.;
          gap(node.dofs[0])      = state.gap;
        }
    if (pairs)
      pairs->nodal_fields(u, residual, pressure, gap);
  }

  template <int dim>
  typename ContactSet<dim>::NodeState ContactSet<dim>::state_of(const Node &node, const PETScWrappers::MPI::Vector &u,
                                                                const PETScWrappers::MPI::Vector &residual,
                                                                const double load_factor) const
  {
    NodeState state;
    state.x = position(node, u);
    nearest(node, state.x, load_factor, state.nearest_gap, state.normal);
    state.gap = state.nearest_gap;
    if (node.active >= 0)
      {
        state.gap = obstacles[node.active].gap(state.x, load_factor, state.normal);
        for (unsigned int d = 0; d < dim; ++d)
          state.force -= residual(node.dofs[d]) * state.normal[d];
      }
    return state;
  }

  template <int dim>
  void ContactSet<dim>::write_csv(const std::string &file, const PETScWrappers::MPI::Vector &u,
                                  const PETScWrappers::MPI::Vector &residual, const double load_factor) const
  {
    constexpr unsigned int record = 2 * dim + 5; // reference, position, gap, force, area, pressure, obstacle
    std::vector<double>    local;
    for (const auto &node : nodes)
      if (node.owned)
        {
          const auto state = state_of(node, u, residual, load_factor);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(node.reference[d]);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(state.x[d]);
          local.insert(local.end(), {state.gap, state.force, node.area, node.area > 0 ? state.force / node.area : 0.,
                                     double(node.active)});
        }
    if (pairs)
      pairs->append_rows(u, residual, obstacles.size(), local);
    const auto parts = Utilities::MPI::gather(communicator, local);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    std::vector<std::vector<double>> rows;
    for (const auto &part : parts)
      for (std::size_t k = 0; k + record <= part.size(); k += record)
        rows.emplace_back(part.begin() + k, part.begin() + k + record);
    std::sort(rows.begin(), rows.end());
    std::ofstream  out(file);
    const char    *axes[]    = {"x", "y", "z"};
    const auto     all_names = names();
    for (unsigned int d = 0; d < dim; ++d)
      out << "reference_" << axes[d] << ",";
    for (unsigned int d = 0; d < dim; ++d)
      out << axes[d] << ",";
    out << "gap,force,area,pressure,obstacle\n" << std::setprecision(12);
    for (const auto &row : rows)
      {
        for (unsigned int k = 0; k + 1 < record; ++k)
          out << row[k] << ",";
        out << (row.back() >= 0 ? all_names[static_cast<unsigned int>(row.back())] : std::string()) << "\n";
      }
  }

  template class ContactSet<2>;
  template class ContactSet<3>;
} // namespace compliant
