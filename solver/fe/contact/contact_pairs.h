// Contact between two boundaries of the part (Contact/Pairs): a link meeting its stop, two bodies
// of one mesh pressed together, a part folding onto itself. Frictionless, by the same primal-dual
// active set as the rigid obstacles (contact_set.h), in mortar form so that a uniform pressure
// passes exactly across a flat contact also where the two meshes do not match:
// every node j of the slave boundary carries the weighted gap
//   g_j = int N_j (x - y(x)) . n dA / D_j,   D_j = int N_j dA,
// over the slave surface where it faces the master (y(x): x's projection onto the master surface,
// n its outward normal there), and, held, the linearised constraint
//   n_j . du_j - sum_k (M_jk / D_j) n_j . du_k = -g_j,   M_jk = int N_j N_k(y(x)) dA,
// on its component most aligned with the averaged normal n_j (k: the master surface's nodes). The
// rows of M / D sum to one, so the constraint moves with a rigid motion of both sides, and the
// slave's contact forces reach the master as the M / D weighted share (action and reaction).
// The integrals are exact on flat faces in 2D (each slave face split where the master's nodes
// project), on 4 x 4 sub-squares per face in 3D. Both surfaces are known on every rank.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/petsc_vector.h>

#include "contact/contact_surface.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace compliant
{
  struct ContactPair
  {
    std::string   name;
    std::set<int> slave, master; // boundary ids
  };
  // Parses Contact/Pairs: 'name: slave=b1 b2, master=b3; ...'; throws std::invalid_argument
  // naming the entry and what was expected.
  std::vector<ContactPair> parse_contact_pairs(const std::string &spec, const std::map<std::string, int> &boundaries);

  template <int dim>
  class ContactPairs
  {
  public:
    // excluded: boundaries whose nodes never hold (rigid boundaries). thickness: of a 2D model
    // (areas); tolerance: the penetration allowed, a length. Collective.
    ContactPairs(const std::vector<ContactPair> &pairs, const std::set<int> &excluded,
                 const dealii::DoFHandler<dim> &dofs, const dealii::Mapping<dim> &mapping,
                 const dealii::IndexSet &owned, const dealii::IndexSet &relevant, double thickness, double tolerance,
                 MPI_Comm communicator);

    // The active set at state u (ghosted) from the unconstrained residual r = f_ext - f_int
    // (owned), as ContactSet::update_active_set; adds to changes, pulling and violation. Collective.
    void update_active_set(const dealii::PETScWrappers::MPI::Vector &u,
                           const dealii::PETScWrappers::MPI::Vector &residual, bool release, double force_tolerance,
                           unsigned int &changes, unsigned int &closed, unsigned int &pulling, double &violation);
    // The held nodes' constraints on the correction at state u (the mortar data of u). Collective.
    void add_constraints(dealii::AffineConstraints<double> &constraints, const dealii::PETScWrappers::MPI::Vector &u,
                         bool homogeneous);

    struct PairResult
    {
      dealii::Tensor<1, dim> force;  // on the slave side (the master carries -force)
      dealii::Tensor<1, 3>   moment; // about the origin, deformed positions
      unsigned int           nodes = 0;
    };
    // Forces of the held nodes, and the deepest penetration of any slave node. Collective.
    std::vector<PairResult> result(const dealii::PETScWrappers::MPI::Vector &u,
                                   const dealii::PETScWrappers::MPI::Vector &residual, double &max_penetration);
    // Rows of contact.csv for the slave nodes this rank owns (reference, position, gap, force,
    // area, pressure, name index = first_index + pair), and the nodal fields.
    void append_rows(const dealii::PETScWrappers::MPI::Vector &u, const dealii::PETScWrappers::MPI::Vector &residual,
                     double first_index, std::vector<double> &rows);
    void nodal_fields(const dealii::PETScWrappers::MPI::Vector &u, const dealii::PETScWrappers::MPI::Vector &residual,
                      dealii::PETScWrappers::MPI::Vector &pressure, dealii::PETScWrappers::MPI::Vector &gap);

    void release_all();
    // The active set at a converged state, and back to it after a failed step (a Newton that
    // failed leaves nodes held that its attempt pulled into contact, far from the state it
    // returns to).
    void save()
    {
      for (auto &side : sides)
        side.saved_active = side.active;
    }
    void restore()
    {
      for (auto &side : sides)
        if (side.saved_active.size() == side.active.size())
          side.active = side.saved_active;
    }
    const std::vector<ContactPair> &pairs() const { return contact_pairs; }

  private:
    struct Mortar
    {
      double                                    weight = 0; // D_j: where a master face is behind
      double                                    gap    = 0; // the weighted gap g_j
      dealii::Tensor<1, dim>                    normal;
      std::vector<std::pair<unsigned, double>> masters; // master node, M_jk / D_j
    };
    struct Side
    {
      std::unique_ptr<ContactSurface<dim>> slave, master;
      std::vector<bool>                    candidate; // per slave node: may hold (not on the master, not excluded)
      std::vector<int>                     active;    // per slave node: 1 held (the owner decides)
      std::vector<int>                     saved_active;
      std::vector<double>                  area;      // per slave node: int N_j dA at rest (times thickness)
      std::vector<Mortar>                  mortar;    // per slave node, at the last refresh
    };
    std::vector<ContactPair> contact_pairs;
    std::vector<Side>        sides;
    dealii::IndexSet         owned_dofs, relevant_dofs;
    double                   thickness, tolerance;
    MPI_Comm                 communicator;

    // Both surfaces of every pair at state u, and the mortar data of every slave node this rank
    // sees. Collective.
    void refresh(const dealii::PETScWrappers::MPI::Vector &u);
    // The surfaces' displacements of the last refresh (all ranks alike).
    std::map<dealii::types::global_dof_index, double> refreshed_at;
    bool                                              refreshed = false;
    void integrate(Side &side, bool at_rest) const;
    bool relevant(const typename ContactSurface<dim>::Node &node) const
    {
      return relevant_dofs.is_element(node.dofs[0]);
    }
    bool owned(const typename ContactSurface<dim>::Node &node) const { return owned_dofs.is_element(node.dofs[0]); }
    // The contact force of a held slave node along its normal (from its owned residual).
    double force_of(const Side &side, unsigned int node, const dealii::PETScWrappers::MPI::Vector &residual) const;
  };
} // namespace compliant
