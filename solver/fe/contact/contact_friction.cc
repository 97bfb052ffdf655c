// Coulomb friction of held contact nodes (contact/contact_set.h): stick, slip, the friction forces.
#include "contact/contact_set.h"

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // The obstacle's force on a held node: minus its residual (the node's reaction).
    template <int dim, typename HeldNode>
    Tensor<1, dim> obstacle_force(const HeldNode &node, const PETScWrappers::MPI::Vector &residual)
    {
      Tensor<1, dim> f;
      for (unsigned int d = 0; d < dim; ++d)
        f[d] = -residual(node.dofs[d]);
      return f;
    }
  } // namespace

  template <int dim>
  bool ContactSet<dim>::has_friction() const
  {
    return std::any_of(obstacles.begin(), obstacles.end(), [](const auto &o) { return o.friction > 0; });
  }

  template <int dim>
  void ContactSet<dim>::stick_at(Node &node, const Point<dim> &x, const double gap, const Tensor<1, dim> &n,
                                 const double load_factor) const
  {
    node.anchor       = x - gap * n; // onto the surface
    node.anchor_load  = load_factor;
    node.anchor_obstacle = -1; // set to the obstacle that holds it (update_active_set, start_step)
    node.slip         = false;
    node.normal_force = 0;
  }

  template <int dim>
  Point<dim> ContactSet<dim>::stick_target(const Node &node, const double load_factor) const
  {
    return node.anchor + (load_factor - node.anchor_load) * obstacles[node.active].motion;
  }

  template <int dim>
  void ContactSet<dim>::update_friction(Node &node, const Point<dim> &x, const double gap, const Tensor<1, dim> &n,
                                        const PETScWrappers::MPI::Vector &residual, const double load_factor,
                                        const bool release, const double force_tolerance, Update &update) const
  {
    const double   mu = obstacles[node.active].friction;
    const Tensor<1, dim> f          = obstacle_force<dim>(node, residual);
    const double         normal     = f * n;
    const Tensor<1, dim> tangential = f - normal * n;
    if (!node.slip)
      {
        // Beyond the cone: the part slides opposite to the tangential force that held it.
        if (release && tangential.norm() > mu * std::max(normal, 0.) + force_tolerance)
          {
            node.slip           = true;
            node.slip_direction = -tangential / tangential.norm();
            node.normal_force   = std::max(normal, 0.);
            node.slip_length    = 0;
            ++update.changes;
          }
        return;
      }
    node.normal_force = std::max(normal, 0.);
    Tensor<1, dim> slid = x - stick_target(node, load_factor);
    slid -= (slid * n) * n;
    node.slip_length = slid.norm();
    if (slid.norm() <= tolerance)
      return;
    const Tensor<1, dim> direction = slid / slid.norm();
    // Slid back against the friction that pushed it (near equilibrium): it sticks where it is.
    if (release && direction * node.slip_direction < 0)
      {
        const int held = node.active;
        stick_at(node, x, gap, n, load_factor);
        node.anchor_obstacle = held;
        ++update.changes;
        return;
      }
    node.slip_direction = direction;
  }

  template <int dim>
  void ContactSet<dim>::start_step(const PETScWrappers::MPI::Vector &u, const double load_factor)
  {
    for (auto &node : nodes)
      {
        node.step_anchor = frictional(node);
        if (!node.step_anchor)
          continue;
        const Point<dim> x = position(node, u);
        Tensor<1, dim>   n;
        const double     gap = obstacles[node.active].gap(x, load_factor, n);
        stick_at(node, x, gap, n, load_factor);
        node.anchor_obstacle = node.active;
      }
  }

  template <int dim>
  Tensor<1, dim> ContactSet<dim>::contact_force(const Node &node, const Tensor<1, dim> &normal, const double force,
                                                const PETScWrappers::MPI::Vector &residual) const
  {
    const double mu = frictional(node) ? obstacles[node.active].friction : 0.;
    if (mu > 0 && !node.slip)
      return obstacle_force<dim>(node, residual);
    Tensor<1, dim> f = force * normal;
    if (mu > 0)
      f -= mu * node.normal_force * node.slip_direction;
    return f;
  }

  template <int dim>
  void ContactSet<dim>::add_friction_forces(const AffineConstraints<double> *constraints,
                                            PETScWrappers::MPI::Vector &residual, PETScWrappers::MPI::Vector *full) const
  {
    Vector<double>                       force(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const auto &node : nodes)
      if (node.owned && node.slip && frictional(node))
        {
          for (unsigned int d = 0; d < dim; ++d)
            force[d] = -obstacles[node.active].friction * node.normal_force * node.slip_direction[d], dofs[d] = node.dofs[d];
          if (constraints != nullptr)
            constraints->distribute_local_to_global(force, dofs, residual);
          else
            residual.add(dofs, force);
          if (full != nullptr)
            full->add(dofs, force);
        }
  }

  template <int dim>
  void ContactSet<dim>::add_friction_stiffness(const AffineConstraints<double> *constraints,
                                               PETScWrappers::MPI::SparseMatrix &tangent) const
  {
    if (dim == 2)
      return; // the slip direction can only reverse
    FullMatrix<double>                   stiffness(dim, dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const auto &node : nodes)
      if (node.owned && node.slip && frictional(node))
        {
          Tensor<1, dim> n;
          obstacles[node.active].gap(node.anchor, node.anchor_load, n); // the surface's normal there
          // Slips shorter than the tolerance: the direction is barely defined; stiff across it.
          const double k = obstacles[node.active].friction * node.normal_force / std::max(node.slip_length, tolerance);
          for (unsigned int i = 0; i < dim; ++i)
            {
              dofs[i] = node.dofs[i];
              for (unsigned int j = 0; j < dim; ++j)
                stiffness(i, j) = k * ((i == j ? 1. : 0.) - n[i] * n[j] - node.slip_direction[i] * node.slip_direction[j]);
            }
          if (constraints != nullptr)
            constraints->distribute_local_to_global(stiffness, dofs, tangent);
          else
            tangent.add(dofs, stiffness);
        }
  }

  template void ContactSet<2>::add_friction_stiffness(const AffineConstraints<double> *,
                                                      PETScWrappers::MPI::SparseMatrix &) const;
  template void ContactSet<3>::add_friction_stiffness(const AffineConstraints<double> *,
                                                      PETScWrappers::MPI::SparseMatrix &) const;
  template void ContactSet<2>::start_step(const PETScWrappers::MPI::Vector &, double);
  template void ContactSet<3>::start_step(const PETScWrappers::MPI::Vector &, double);
  template bool ContactSet<2>::has_friction() const;
  template bool ContactSet<3>::has_friction() const;
  template void ContactSet<2>::stick_at(Node &, const Point<2> &, double, const Tensor<1, 2> &, double) const;
  template void ContactSet<3>::stick_at(Node &, const Point<3> &, double, const Tensor<1, 3> &, double) const;
  template Point<2> ContactSet<2>::stick_target(const Node &, double) const;
  template Point<3> ContactSet<3>::stick_target(const Node &, double) const;
  template void ContactSet<2>::update_friction(Node &, const Point<2> &, double, const Tensor<1, 2> &,
                                               const PETScWrappers::MPI::Vector &, double, bool, double, Update &) const;
  template void ContactSet<3>::update_friction(Node &, const Point<3> &, double, const Tensor<1, 3> &,
                                               const PETScWrappers::MPI::Vector &, double, bool, double, Update &) const;
  template Tensor<1, 2> ContactSet<2>::contact_force(const Node &, const Tensor<1, 2> &, double,
                                                     const PETScWrappers::MPI::Vector &) const;
  template Tensor<1, 3> ContactSet<3>::contact_force(const Node &, const Tensor<1, 3> &, double,
                                                     const PETScWrappers::MPI::Vector &) const;
  template void ContactSet<2>::add_friction_forces(const AffineConstraints<double> *, PETScWrappers::MPI::Vector &,
                                                   PETScWrappers::MPI::Vector *) const;
  template void ContactSet<3>::add_friction_forces(const AffineConstraints<double> *, PETScWrappers::MPI::Vector &,
                                                   PETScWrappers::MPI::Vector *) const;
} // namespace compliant
