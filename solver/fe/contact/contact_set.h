// Frictionless contact of the part's boundary nodes with rigid obstacles, by a primal-dual active
// set (semismooth Newton; deal.II step-41 for a linear problem, here inside the finite-strain
// Newton iteration). Each node of a contact boundary is either free or active, held on one
// obstacle by the linearised constraint n . du = -gap (one multi-point constraint per node, on its
// component most aligned with n), so the active nodes slide freely along the surface. The set is
// chosen again at every Newton iteration: a free node that penetrates becomes active, an active
// node whose contact force lambda = -n . r (r = f_ext - f_int) would pull (lambda <= 0) is freed.
// (The semismooth form lambda - c gap > 0 with a stiffness-sized c freed nodes a curved obstacle
// leaves a second-order gap under after a linearised step, and they came back every other
// iteration; an active node's gap is closed by its constraint anyway.) Newton has converged only
// when the set no longer changes and no node lies deeper than the tolerance: there is no penalty
// stiffness for the answer to depend on.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_vector.h>

#include "contact/contact_obstacle.h"

#include <array>
#include <set>
#include <string>
#include <vector>

namespace compliant
{
  template <int dim>
  class ContactSet
  {
  public:
    // Gathers the nodes of the obstacles' boundaries on this rank's cells (owned and ghost);
    // nodes on an `excluded` boundary (a rigid boundary: its nodes are already tied) are left
    // out. thickness: of a 2D model, for the nodes' areas; tolerance: fraction of the part's size.
    // Collective.
    ContactSet(std::vector<Obstacle<dim>> obstacles, const std::set<int> &excluded,
               const dealii::DoFHandler<dim> &dofs, const dealii::Mapping<dim> &mapping,
               const dealii::Quadrature<dim - 1> &face_quadrature, const dealii::IndexSet &owned,
               const dealii::IndexSet &relevant, double thickness, double tolerance,
               MPI_Comm communicator);

    struct Update
    {
      unsigned int changes   = 0; // nodes that became active or free (all ranks)
      unsigned int pulling   = 0; // active nodes whose contact force pulls (freed only if `release`)
      double       violation = 0; // deepest penetration, or largest gap of an active node
    };
    // Chooses the active set at state u (ghosted) from the residual r = f_ext - f_int (owned,
    // unconstrained) at the load factor. A penetrating node is held at once; a held node that
    // pulls is freed only with `release`: its force means something only near equilibrium (a
    // node freed on the force of the state one step after it was held came back every other
    // iteration), and only if it pulls by more than force_tolerance (Newton's residual
    // tolerance); a free node is held when it is deeper than the tolerance. Collective.
    Update update_active_set(const dealii::PETScWrappers::MPI::Vector &u,
                             const dealii::PETScWrappers::MPI::Vector &residual, double load_factor, bool release,
                             double force_tolerance);

    // Adds the constraint of every active node on the correction du at state u:
    // n . du = -gap (homogeneous: = 0). Components already constrained are kept out; a node whose
    // free components cannot move along n is left free.
    void add_constraints(dealii::AffineConstraints<double> &constraints,
                         const dealii::PETScWrappers::MPI::Vector &u, double load_factor,
                         bool homogeneous) const;

    struct ObstacleResult
    {
      dealii::Tensor<1, dim> force;  // on the part
      dealii::Tensor<1, 3>   moment; // about the origin, at the deformed positions
      unsigned int           nodes = 0;
    };
    struct Result
    {
      std::vector<ObstacleResult> obstacles;
      unsigned int                active_nodes    = 0;
      double                      max_penetration = 0;
    };
    // Forces from the converged residual (r = f_ext - f_int, owned). Collective.
    Result result(const dealii::PETScWrappers::MPI::Vector &u, const dealii::PETScWrappers::MPI::Vector &residual,
                  double load_factor) const;

    // contact.csv: every contact node, its reference and deformed position, gap, contact force
    // and pressure (force / lumped area). Collective; rank 0 writes.
    void write_csv(const std::string &file, const dealii::PETScWrappers::MPI::Vector &u,
                   const dealii::PETScWrappers::MPI::Vector &residual, double load_factor) const;

    // The contact pressure (force along the normal over the lumped area; 0 on a free node) and
    // the gap to the nearest obstacle at every contact node, written at the node's first
    // displacement DoF of `pressure` and `gap` (owned vectors of the problem's DoFs, zero
    // elsewhere; compress(insert) after). Collective.
    void nodal_fields(const dealii::PETScWrappers::MPI::Vector &u, const dealii::PETScWrappers::MPI::Vector &residual,
                      double load_factor, dealii::PETScWrappers::MPI::Vector &pressure,
                      dealii::PETScWrappers::MPI::Vector &gap) const;

    // Frees every node (a path restarted from rest).
    void release_all()
    {
      for (auto &node : nodes)
        node.active = -1;
    }

    const std::vector<Obstacle<dim>> obstacles;
    double                           tolerance = 0; // absolute, a length

  private:
    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      dealii::Point<dim>                               reference;
      std::vector<bool>                                allowed; // per obstacle
      double                                           area = 0;
      bool                                             owned = false;
      int                                              active = -1; // obstacle index, or free
    };
    std::vector<Node> nodes;
    MPI_Comm          communicator;
    dealii::IndexSet  owned_dofs, relevant_dofs;

    dealii::Point<dim> position(const Node &node, const dealii::PETScWrappers::MPI::Vector &u) const;
    // The obstacle of a free node: the one it is nearest to (or deepest in).
    unsigned int nearest(const Node &node, const dealii::Point<dim> &x, double load_factor, double &gap,
                         dealii::Tensor<1, dim> &normal) const;
    void         share_active_set(); // the owners' decisions to the ranks that see a node as ghost
    // A node at state u: its position, the gap to the nearest obstacle, and, if held, the gap to
    // its obstacle, the normal there and the contact force along it (from r = f_ext - f_int).
    struct NodeState
    {
      dealii::Point<dim>     x;
      dealii::Tensor<1, dim> normal;
      double                 nearest_gap = 0, gap = 0, force = 0;
    };
    NodeState state_of(const Node &node, const dealii::PETScWrappers::MPI::Vector &u,
                       const dealii::PETScWrappers::MPI::Vector &residual, double load_factor) const;
  };
} // namespace compliant
