// A boundary that moves as a rigid body under a dead force and moment (Boundary conditions/Rigid),
// its translation and rotation unknowns: a torque drive or a pure end moment.
//
// Every DoF of the boundary follows dim (2D: 3, 3D: 6) master DoFs of the same boundary through a
// linear multi-point constraint: the rigid motion linearised about the current position,
// du = dU + dpsi x (x - x_p), about the pivot x_p (the centroid). A Newton correction therefore moves the boundary rigidly to first
// order; move() then puts it on the exact rigid motion (rotation by Rodrigues' formula), so any
// rotation (a cantilever rolled into a full circle) is reached without drift. The load enters as
// nodal forces on a few DoFs whose resultant and moment about the centre are the given ones,
// which is all a rigid boundary can feel. Linear analyses linearise once about the reference.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>

#include "discretization/boundary_conditions.h"

#include <vector>

namespace compliant
{
  template <int dim>
  class RigidBoundary
  {
  public:
    static constexpr unsigned int n_motions = dim == 2 ? 3 : 6; // translations, then rotations

    // Gathers the boundary's DoFs from every rank; DoFs constrained in `hanging` (hanging nodes
    // of adaptive meshes) follow their masters and are left out. Collective. Throws
    // std::invalid_argument if the boundary cannot carry a rigid motion (no nodes; in 3D, nodes
    // on one line).
    RigidBoundary(const RigidBoundaryLoad<dim> &load, const dealii::DoFHandler<dim> &dofs,
                  const dealii::Mapping<dim> &mapping, const dealii::AffineConstraints<double> &hanging,
                  MPI_Comm communicator);

    // Linearises the rigid motion at the state u, which must be exactly rigid on this boundary
    // (nullptr: the reference configuration), and chooses the master DoFs. Collective.
    void linearize(const dealii::PETScWrappers::MPI::Vector *u);

    // Adds slave = sum_m c_m master for every locally relevant DoF of the boundary but the
    // masters. for_sparsity: every slave couples to every DoF a master could be chosen from
    // (the pattern of a matrix whose masters may change with the rotation). Throws
    // std::invalid_argument (collectively) if a DoF is already constrained by a support.
    void add_constraints(dealii::AffineConstraints<double> &constraints, bool for_sparsity = false) const;

    // The DoFs the constraints may name as masters: rows a sparsity pattern must hold.
    dealii::IndexSet master_candidates(dealii::types::global_dof_index n_dofs) const;
    // Every DoF of the boundary (from every rank): its lines hold no rigid motion of the part.
    dealii::IndexSet dofs(dealii::types::global_dof_index n_dofs) const;

    // Couples every candidate to every DoF of the locally owned cells that hold a candidate: a
    // candidate that is a slave in some state (3 of them master, the others follow) condenses
    // onto the other candidates from cells that touch no other node of the boundary (a rigid
    // piece inside a surface: the cells beside it). Without these entries PETSc drops the
    // values silently and Newton stalls.
    void add_candidate_couplings(const dealii::DoFHandler<dim> &dofs,
                                 dealii::DynamicSparsityPattern &pattern) const;

    // Adds scale * (force, moment) to rhs as nodal forces (through constraints if given).
    // Every rank calls it; rank 0 adds. Needs rhs.compress(add) afterwards.
    void add_load(double scale, const dealii::AffineConstraints<double> *constraints,
                  dealii::PETScWrappers::MPI::Vector &rhs) const;

    // Adds to the condensed tangent the change of the constraint's rotation columns with the
    // rotation, weighted by the forces the body exerts on the boundary, f = -residual
    // (residual = f_ext - f_int unconstrained, without this boundary's load): A_jk =
    // sum_s r_j f_k - (f . r) delta_jk on the rotations, T^T A T on the masters. Without it
    // Newton stalls in 3D, where the bending stresses couple the rotations. Unsymmetric in 3D
    // (a space-fixed moment is not conservative). Collective; rank 0 adds, compress(add) after.
    // scale: the load factor of this boundary's force, which adds its own term when the load
    // point is off the pivot.
    void add_geometric_stiffness(const dealii::PETScWrappers::MPI::Vector &residual, double scale,
                                 dealii::PETScWrappers::MPI::SparseMatrix &matrix) const;

    // u (owned entries) gets the exact rigid motion reached from the linearised state by the
    // correction alpha * du (du satisfies the constraints). Collective; u needs no compress.
    void move(const dealii::PETScWrappers::MPI::Vector &du, double alpha,
              dealii::PETScWrappers::MPI::Vector &u) const;

    struct Motion
    {
      dealii::Tensor<1, 3>   rotation;     // rotation vector, continued past pi from the previous state
      dealii::Tensor<1, dim> displacement; // of the centre
    };
    // The rigid motion of the boundary in the state u. Collective.
    Motion motion(const dealii::PETScWrappers::MPI::Vector &u, bool geometrically_nonlinear) const;

    // Continues the reported rotation from `other`'s (the same boundary of another model of the
    // case, at a nearby state) instead of from this one's last: a state carried from another
    // model has no path of its own to continue a rotation past pi along.
    void continue_rotation_from(const RigidBoundary &other)
    {
      last_angle    = other.last_angle;
      last_rotation = other.last_rotation;
    }
    // Continues it from the reference configuration again (a path restarted from rest).
    void forget_rotation()
    {
      last_angle    = 0;
      last_rotation = dealii::Tensor<1, 3>();
    }

    const RigidBoundaryLoad<dim> load;
    dealii::Point<dim>           center; // reference position of the load point (the force acts
                                         // there; its displacement is reported)
    // The point the rigid motion is linearised about: the centroid of the boundary's nodes. A
    // load point far from the nodes (a spar 200 mm out on an arm) would make the linearisation
    // error (distance x rotation^2) and so the jump of each exact projection large: Newton then
    // wandered for 16 iterations per small step, where the centroid needs 4.
    dealii::Point<dim> pivot;

  private:
    struct BoundaryDof
    {
      dealii::types::global_dof_index index;
      unsigned int                    component;
      dealii::Point<dim>              point;
    };
    std::vector<BoundaryDof>  boundary_dofs;
    std::vector<unsigned int> candidates; // all components of 2 (2D) or 3 (3D) spread-out nodes
    double                    size = 1;   // largest distance of a candidate from the pivot
    MPI_Comm                  communicator;

    // The linearisation: rotation and centre position of the state, masters, and the map from
    // master values to (dU, dpsi).
    dealii::Tensor<2, dim>     rotation;
    dealii::Point<dim>         center_position;
    std::vector<unsigned int>  masters; // into boundary_dofs
    dealii::FullMatrix<double> master_to_motion;
    mutable double             last_angle = 0; // 2D: to continue the angle past pi
    mutable dealii::Tensor<1, 3> last_rotation;  // 3D: to continue the rotation vector past pi

    // Row of d(u_i at x) / d(dU, dpsi) at the current position x_current - x_c = r.
    std::vector<double> motion_row(unsigned int component, const dealii::Tensor<1, dim> &r) const;
    // Owned values of v at the candidates, summed over the ranks.
    std::vector<double> candidate_values(const dealii::PETScWrappers::MPI::Vector &v) const;
    void                frame_from(const std::vector<double> &values,
                                   dealii::Tensor<2, dim> &rotation, dealii::Point<dim> &center_position) const;
  };

  // The matrix of a problem with rigid boundaries: the pattern of `constraints` (which name every
  // candidate master, RigidBoundary::add_constraints with for_sparsity), the rows of the master
  // candidates and their couplings (add_candidate_couplings). keep_constrained: constrained rows
  // keep their cells' couplings too (a contact node held now may be freed later; PETSc drops
  // entries outside the pattern without a word).
  template <int dim>
  void reinit_matrix(dealii::PETScWrappers::MPI::SparseMatrix &matrix, const dealii::DoFHandler<dim> &dofs,
                     const dealii::AffineConstraints<double> &constraints,
                     const std::vector<RigidBoundary<dim>> &rigid_boundaries, const dealii::IndexSet &owned,
                     const dealii::IndexSet &relevant, MPI_Comm communicator, bool keep_constrained = false);
} // namespace compliant
