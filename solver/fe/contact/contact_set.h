// Contact of the part's boundary nodes with rigid obstacles, by a primal-dual active
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
// Coulomb friction (an obstacle's friction mu > 0, contact/contact_friction.cc): a node that comes
// into contact sticks, held in every direction at its point of the surface, which moves with the
// obstacle; near equilibrium a sticking node whose tangential force exceeds mu times its normal
// force slips: it is held on the surface by the normal constraint alone and pushed back by mu times
// its normal force (that of the last iterate: a fixed point inside Newton) against its slip within
// the step (the tangent has the force's turning with the slip in 3D). Every load step starts with
// the held nodes sticking where the last one left them (start_step).
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "contact/contact_obstacle.h"
#include "contact/contact_pairs.h"

#include <array>
#include <memory>
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
    // Nodes on a `supported` boundary (clamped, displaced in every component, turned) touch
    // without friction: the support holds them tangentially, and their reaction is the support's.
    // Collective.
    ContactSet(std::vector<Obstacle<dim>> obstacles, const std::set<int> &excluded, const std::set<int> &supported,
               const dealii::DoFHandler<dim> &dofs, const dealii::Mapping<dim> &mapping,
               const dealii::Quadrature<dim - 1> &face_quadrature, const dealii::IndexSet &owned,
               const dealii::IndexSet &relevant, double thickness, double tolerance,
               MPI_Comm communicator);

    struct Update
    {
      unsigned int changes   = 0; // nodes that became active or free (all ranks)
      unsigned int closed    = 0; // of them, nodes that became active (all ranks)
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
    // n . du = -gap (homogeneous: = 0), or a sticking node's du = its anchor (moved with the
    // obstacle since) - x in every component. Components already constrained are kept out; a node whose free components cannot
    // move along n is left free.
    void add_constraints(dealii::AffineConstraints<double> &constraints,
                         const dealii::PETScWrappers::MPI::Vector &u, double load_factor,
                         bool homogeneous) const;

    // The friction forces of the slipping nodes this rank owns (-mu times the normal force of the
    // last update along the slip direction) added to the residual r = f_ext - f_int: condensed
    // through `constraints` (nodal without), and nodal into `full`. Before compress(add).
    void add_friction_forces(const dealii::AffineConstraints<double> *constraints,
                             dealii::PETScWrappers::MPI::Vector &residual, dealii::PETScWrappers::MPI::Vector *full) const;
    // The friction forces' derivative for the tangent: a slipping node's force -mu N s / |s| turns
    // with its slip s, a stiffness mu N / |s| across the slip in the surface (zero in 2D).
    // Condensed through `constraints` (nodal without); before compress(add).
    void add_friction_stiffness(const dealii::AffineConstraints<double> *constraints,
                                dealii::PETScWrappers::MPI::SparseMatrix &tangent) const;
    bool has_friction() const;

    struct ObstacleResult
    {
      dealii::Tensor<1, dim> force;  // on the part (normal and friction)
      dealii::Tensor<1, 3>   moment; // about the origin, at the deformed positions
      unsigned int           nodes = 0;
      unsigned int           sticking = 0, slipping = 0; // with friction
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

    // Friction: a load step starts from its converged state (u, ghosted) with every held node
    // sticking where it is (the trial state of a return mapping); it slips within the step
    // once the cone is exceeded, relative to there.
    void start_step(const dealii::PETScWrappers::MPI::Vector &u, double load_factor);
    // Remembers every node's state (held or free; with friction stick or slip, anchor) at a
    // converged state, and returns to it after a failed or rejected step (a failed Newton leaves
    // its own).
    void save() { saved_nodes = nodes; }
    void restore()
    {
      if (saved_nodes.size() == nodes.size())
        nodes = saved_nodes;
    }

    // Throws std::invalid_argument naming the obstacle where one moves or has friction: `what`
    // (a path driver) needs contact that depends on the state alone, not on the load factor or
    // the path to it.
    void require_fixed_frictionless(const std::string &what) const;

    // Frees every node (a path restarted from rest).
    void release_all()
    {
      for (auto &node : nodes)
        node.active = -1, node.slip = false, node.step_anchor = false;
      if (pairs)
        pairs->release_all();
    }

    const std::vector<Obstacle<dim>> obstacles;
    double                           tolerance = 0; // absolute, a length
    // Boundaries of the part touching each other (Contact/Pairs), if any: every call above
    // covers them too; their results follow the obstacles' (names()).
    std::unique_ptr<ContactPairs<dim>> pairs;
    // The obstacles' names, then the pairs'.
    std::vector<std::string> names() const;

  private:
    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs;
      dealii::Point<dim>                               reference;
      std::vector<bool>                                allowed; // per obstacle
      double                                           area = 0;
      bool                                             owned = false;
      bool                                             supported = false; // no friction
      int                                              active = -1; // obstacle index, or free
      // With friction: sticking at `anchor` (a point of the surface, moving with the obstacle
      // from load factor anchor_load on) or slipping along slip_direction (the part's motion
      // relative to the obstacle) under the normal force of the last update.
      bool                   slip = false;
      dealii::Point<dim>     anchor;
      double                 anchor_load = 0, normal_force = 0, slip_length = 0;
      bool                   step_anchor = false; // anchored by start_step: kept if freed sticking and held again
      int                    anchor_obstacle = -1; // the obstacle the anchor lies on
      dealii::Tensor<1, dim> slip_direction;
    };
    std::vector<Node> nodes, saved_nodes;
    // Whether a held node is under friction (its obstacle has some, and no support holds it).
    bool frictional(const Node &node) const
    {
      return node.active >= 0 && !node.supported && obstacles[node.active].friction > 0;
    }

    MPI_Comm          communicator;
    dealii::IndexSet  owned_dofs, relevant_dofs;

    dealii::Point<dim> position(const Node &node, const dealii::PETScWrappers::MPI::Vector &u) const;
    // The obstacle of a free node: the one it is nearest to (or deepest in).
    unsigned int nearest(const Node &node, const dealii::Point<dim> &x, double load_factor, double &gap,
                         dealii::Tensor<1, dim> &normal) const;
    // The owners' decisions (active set, stick or slip, anchors) to the ranks that see a node as ghost.
    void         share_active_set();
    // Friction: a node coming into contact at x (gap, normal n) sticks at its point of the surface.
    void         stick_at(Node &node, const dealii::Point<dim> &x, double gap, const dealii::Tensor<1, dim> &n,
                          double load_factor) const;
    // Where a sticking node is held at the load factor.
    dealii::Point<dim> stick_target(const Node &node, double load_factor) const;
    // A held node on an obstacle with friction: stick to slip, slip to stick (its slip reversed),
    // the normal force.
    void update_friction(Node &node, const dealii::Point<dim> &x, double gap, const dealii::Tensor<1, dim> &n,
                         const dealii::PETScWrappers::MPI::Vector &residual, double load_factor, bool release,
                         double force_tolerance, Update &update) const;
    // The force of a held node on the part: -r, or its normal part and the friction of a slipping node.
    // normal and force: the held node's normal and normal force (NodeState).
    dealii::Tensor<1, dim> contact_force(const Node &node, const dealii::Tensor<1, dim> &normal, double force,
                                         const dealii::PETScWrappers::MPI::Vector &residual) const;
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
