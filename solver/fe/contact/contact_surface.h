// A boundary of the part as a contact surface, the same on every rank: its faces' nodes (the
// displacement element's support points: DoFs, reference position), each face parametrized over
// the unit square (segment in 2D) by the Lagrange polynomials of its nodes, so that it follows the
// element exactly (isoparametric), and oriented outward from the body. Contact between two
// boundaries of the part (contact/contact_pairs.h) projects points of one onto the other, on any
// rank, at the current displacement.
#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <mpi.h>

#include <array>
#include <map>
#include <set>
#include <vector>

namespace compliant
{
  template <int dim>
  class ContactSurface
  {
  public:
    struct Node
    {
      std::array<dealii::types::global_dof_index, dim> dofs{};
      dealii::Point<dim>                               reference;
    };
    struct Face
    {
      std::vector<unsigned int>                      nodes; // into nodes()
      std::vector<std::array<unsigned int, dim - 1>> lagrange; // per node: its 1D polynomial per direction
      double orientation = 1; // the sign that makes the normal point out of the body
    };
    // Where a point meets the surface: the face, its parameters there, the point of the surface,
    // the outward unit normal and the signed distance (x - on) . normal.
    struct Projection
    {
      bool                         found = false;
      unsigned int                 face  = 0;
      std::array<double, dim - 1>  xi{};
      dealii::Point<dim>           on;
      dealii::Tensor<1, dim>       normal;
      double                       distance = 0;
    };

    // Gathers the faces of the boundaries `ids` from every rank's owned cells (quadrilaterals and
    // hexahedra; base element 0 of the system is the displacement's FE_Q). Collective.
    ContactSurface(const dealii::DoFHandler<dim> &dofs, const dealii::Mapping<dim> &mapping, const std::set<int> &ids,
                   MPI_Comm communicator);

    // The current positions of the nodes from the displacement (every node's DoFs; collective).
    void update(const std::map<dealii::types::global_dof_index, double> &displacement);
    // The DoFs of this rank's part of the surface (owned cells), for update().
    const std::vector<dealii::types::global_dof_index> &local_dofs() const { return own_dofs; }

    // Shape values of the face's nodes at parameters xi, and the position and tangents there.
    void   shape_values(const Face &face, const std::array<double, dim - 1> &xi, std::vector<double> &values) const;
    dealii::Point<dim> position(const Face &face, const std::array<double, dim - 1> &xi,
                                std::array<dealii::Tensor<1, dim>, dim - 1> *tangents = nullptr) const;
    // The outward unit normal from the tangents, and the area element (length in 2D).
    dealii::Tensor<1, dim> normal(const Face &face, const std::array<dealii::Tensor<1, dim>, dim - 1> &tangents,
                                  double *area_element = nullptr) const;

    // The nearest point of the surface whose projection falls inside a face (within `reach` of x;
    // found = false if none); with `facing`, only faces whose normal opposes it (the two sides of
    // a contact face each other).
    Projection project(const dealii::Point<dim> &x, double reach, const dealii::Tensor<1, dim> *facing = nullptr) const;
    // The parameters of the point of `face` nearest to x, and whether it lies inside the face.
    // Unbounded: the parameters of the face's own extension instead (a point beyond an edge of a
    // flat face gets parameters outside [0, 1]), and true.
    bool closest_on_face(unsigned int face, const dealii::Point<dim> &x, std::array<double, dim - 1> &xi,
                         bool unbounded = false) const;
    // The face's corner nodes in order around it (2 in 2D, 4 in 3D).
    std::vector<unsigned int> corners(const Face &face) const;

    const std::vector<Node> &nodes() const { return surface_nodes; }
    const std::vector<Face> &faces() const { return surface_faces; }
    const dealii::Point<dim> &current(unsigned int node) const { return positions[node]; }
    // A face's bounding box at the current positions.
    const std::pair<dealii::Point<dim>, dealii::Point<dim>> &box(unsigned int face) const { return boxes[face]; }
    // The largest face diameter at the current positions.
    double face_size() const { return largest_face; }

  private:
    std::vector<double>                          support; // 1D Lagrange points in [0, 1]
    std::vector<Node>                            surface_nodes;
    std::vector<Face>                            surface_faces;
    std::vector<dealii::Point<dim>>              positions;
    std::vector<std::pair<dealii::Point<dim>, dealii::Point<dim>>> boxes; // per face, current
    std::vector<dealii::types::global_dof_index> own_dofs;
    double                                       largest_face = 0;

    double lagrange(unsigned int a, double t, double *derivative) const;
  };
} // namespace compliant
