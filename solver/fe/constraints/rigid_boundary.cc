#include "constraints/rigid_boundary.h"

#include "discretization/face_nodes.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // Rotation by the rotation vector psi (Rodrigues); 2D: by psi_z.
    template <int dim>
    Tensor<2, dim> rotation_matrix(const Tensor<1, 3> &psi)
    {
      Tensor<2, dim> R;
      if constexpr (dim == 2)
        {
          const double c = std::cos(psi[2]), s = std::sin(psi[2]);
          R[0][0] = c, R[0][1] = -s, R[1][0] = s, R[1][1] = c;
        }
      else
        {
          const double angle = psi.norm();
          R                  = unit_symmetric_tensor<dim>();
          if (angle > 0)
            {
              const Tensor<1, 3> k = psi / angle;
              Tensor<2, 3>       K;
              K[0][1] = -k[2], K[0][2] = k[1], K[1][0] = k[2], K[1][2] = -k[0], K[2][0] = -k[1],
              K[2][1] = k[0];
              R = std::cos(angle) * R + std::sin(angle) * K + (1 - std::cos(angle)) * outer_product(k, k);
            }
        }
      return R;
    }

    // Orthonormal frame (columns) from two non-parallel vectors.
    Tensor<2, 3> frame(const Tensor<1, 3> &a, const Tensor<1, 3> &b)
    {
      const Tensor<1, 3> e1 = a / a.norm();
      Tensor<1, 3>       e2 = b - (b * e1) * e1;
      e2 /= e2.norm();
      const Tensor<1, 3> e3 = cross_product_3d(e1, e2);
      Tensor<2, 3>       F;
      for (unsigned int i = 0; i < 3; ++i)
        F[i][0] = e1[i], F[i][1] = e2[i], F[i][2] = e3[i];
      return F;
    }
  } // namespace

  template <int dim>
  RigidBoundary<dim>::RigidBoundary(const RigidBoundaryLoad<dim>     &load,
                                    const DoFHandler<dim>            &dofs,
                                    const Mapping<dim>               &mapping,
                                    const AffineConstraints<double>  &hanging,
                                    MPI_Comm                          communicator)
    : load(load), communicator(communicator)
  {
    // Nodes of the boundary on this rank's cells: dim DoF indices, position, hanging flag.
    const auto &fe   = dofs.get_fe();
    const auto &base = fe.base_element(0); // the displacement's FE_Q (a mixed element adds a pressure)
    const Quadrature<dim> support(base.get_unit_support_points());
    FEValues<dim>         fe_values(mapping, fe, support, update_quadrature_points);
    constexpr unsigned int               record = 8; // d0 d1 d2 x y z hanging unused
    std::vector<double>                  local;
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == load.boundary_id)
            {
              for (const auto &[index, face_node] : face_nodes(cell, f, fe_values))
                {
                  std::array<double, record> node{};
                  for (unsigned int d = 0; d < dim; ++d)
                    {
                      node[d]     = face_node.dofs[d];
                      node[3 + d] = face_node.position[d];
                      if (hanging.is_constrained(face_node.dofs[d]))
                        node[6] = 1;
                    }
                  local.insert(local.end(), node.begin(), node.end());
                }
            }
    std::map<types::global_dof_index, std::array<double, record>> all_nodes; // by first DoF
    for (const auto &part : Utilities::MPI::all_gather(communicator, local))
      for (std::size_t k = 0; k + record <= part.size(); k += record)
        {
          std::array<double, record> node;
          std::copy(part.begin() + k, part.begin() + k + record, node.begin());
          all_nodes[static_cast<types::global_dof_index>(node[0])] = node;
        }
    if (all_nodes.empty())
      throw std::invalid_argument("Boundary conditions/Rigid: boundary '" + load.boundary +
                                  "' has no nodes");

    Point<dim> centroid;
    for (const auto &[index, node] : all_nodes)
      for (unsigned int d = 0; d < dim; ++d)
        centroid[d] += node[3 + d] / all_nodes.size();
    pivot  = centroid;
    center = centroid;
    if (load.has_center)
      for (unsigned int d = 0; d < dim; ++d)
        center[d] = load.center[d];

    std::vector<std::pair<Point<dim>, std::array<types::global_dof_index, dim>>> free_nodes;
    for (const auto &[index, node] : all_nodes)
      if (node[6] == 0) // hanging nodes follow their masters
        {
          Point<dim>                                   x;
          std::array<types::global_dof_index, dim> indices;
          for (unsigned int d = 0; d < dim; ++d)
            {
              x[d]       = node[3 + d];
              indices[d] = static_cast<types::global_dof_index>(node[d]);
            }
          for (unsigned int d = 0; d < dim; ++d)
            boundary_dofs.push_back({indices[d], d, x});
          free_nodes.emplace_back(x, indices);
        }

    // Candidates for the masters: every component of two (2D) or three (3D) nodes far apart.
    auto farthest = [&](auto distance) {
      unsigned int best = 0;
      for (unsigned int n = 1; n < free_nodes.size(); ++n)
        if (distance(free_nodes[n].first) > distance(free_nodes[best].first))
          best = n;
      return best;
    };
    std::vector<unsigned int> picked;
    picked.push_back(farthest([&](const Point<dim> &x) { return x.distance(centroid); }));
    const Point<dim> a = free_nodes[picked[0]].first;
    picked.push_back(farthest([&](const Point<dim> &x) { return x.distance(a); }));
    const Point<dim> b = free_nodes[picked[1]].first;
    const double     extent = a.distance(b);
    if (!(extent > 0))
      throw std::invalid_argument("Boundary conditions/Rigid: boundary '" + load.boundary +
                                  "' is a single node; a rigid boundary needs a line (2D) or a "
                                  "surface (3D)");
    if constexpr (dim == 3)
      {
        const Tensor<1, dim> axis = (b - a) / extent;
        auto off_line = [&](const Point<dim> &x) {
          const Tensor<1, dim> r = x - a;
          return (r - (r * axis) * axis).norm();
        };
        picked.push_back(farthest(off_line));
        if (!(off_line(free_nodes[picked[2]].first) > 1e-8 * extent))
          throw std::invalid_argument("Boundary conditions/Rigid: the nodes of boundary '" +
                                      load.boundary + "' lie on one line; in 3D a rigid "
                                      "boundary must be a surface");
      }
    for (const unsigned int n : picked)
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto index = free_nodes[n].second[d];
          const auto it    = std::find_if(boundary_dofs.begin(), boundary_dofs.end(),
                                       [&](const BoundaryDof &b) { return b.index == index; });
          candidates.push_back(it - boundary_dofs.begin());
          size = std::max(size, free_nodes[n].first.distance(pivot));
        }
    linearize(nullptr);
  }

  template <int dim>
  std::vector<double> RigidBoundary<dim>::motion_row(const unsigned int component,
                                                     const Tensor<1, dim> &r) const
  {
    std::vector<double> row(n_motions, 0.);
    row[component] = 1;
    Tensor<1, 3> r3;
    for (unsigned int d = 0; d < dim; ++d)
      r3[d] = r[d];
    if constexpr (dim == 2)
      row[2] = cross_product_3d(Tensor<1, 3>({0., 0., 1.}), r3)[component];
    else
      for (unsigned int j = 0; j < 3; ++j)
        {
          Tensor<1, 3> e;
          e[j]       = 1;
          row[3 + j] = cross_product_3d(e, r3)[component];
        }
    return row;
  }

  template <int dim>
  std::vector<double> RigidBoundary<dim>::candidate_values(const PETScWrappers::MPI::Vector &v) const
  {
    std::vector<double> values(candidates.size(), 0.);
    for (unsigned int k = 0; k < candidates.size(); ++k)
      {
        const auto index = boundary_dofs[candidates[k]].index;
        if (v.in_local_range(index))
          values[k] = v[index];
      }
    MPI_Allreduce(MPI_IN_PLACE, values.data(), values.size(), MPI_DOUBLE, MPI_SUM, communicator);
    return values;
  }

  template <int dim>
  void RigidBoundary<dim>::frame_from(const std::vector<double> &values, Tensor<2, dim> &R,
                                      Point<dim> &x_c) const
  {
    // Candidates come as dim components of node A, then B (then C).
    std::vector<Point<dim>> X, x;
    for (unsigned int n = 0; n * dim < candidates.size(); ++n)
      {
        Point<dim> reference, current;
        for (unsigned int d = 0; d < dim; ++d)
          {
            reference[d] = boundary_dofs[candidates[n * dim + d]].point[d];
            current[d]   = reference[d] + values[n * dim + d];
          }
        X.push_back(reference);
        x.push_back(current);
      }
    if constexpr (dim == 2)
      {
        const Tensor<1, dim> a = X[1] - X[0], b = x[1] - x[0];
        Tensor<1, 3>         psi;
        psi[2] = std::atan2(a[0] * b[1] - a[1] * b[0], a * b);
        R      = rotation_matrix<dim>(psi);
      }
    else
      {
        const Tensor<2, 3> E = frame(X[1] - X[0], X[2] - X[0]), e = frame(x[1] - x[0], x[2] - x[0]);
        R = e * transpose(E);
      }
    x_c = x[0] - R * (X[0] - pivot);
  }

  template <int dim>
  void RigidBoundary<dim>::linearize(const PETScWrappers::MPI::Vector *u)
  {
    if (u == nullptr)
      {
        rotation        = unit_symmetric_tensor<dim>();
        center_position = pivot;
      }
    else
      {
        frame_from(candidate_values(*u), rotation, center_position);
        if constexpr (dim == 2) // Newton moves less than half a turn between linearisations
          last_angle += std::remainder(std::atan2(rotation[1][0], rotation[0][0]) - last_angle, 2 * M_PI);
      }

    // Masters: greedily the candidate rows farthest from the span of those chosen (rotation
    // columns scaled by the boundary's size, so that the choice does not depend on units).
    std::vector<std::vector<double>> basis;
    masters.clear();
    for (unsigned int m = 0; m < n_motions; ++m)
      {
        double       best_norm = -1;
        unsigned int best      = 0;
        std::vector<double> best_residual;
        for (const unsigned int c : candidates)
          {
            if (std::find(masters.begin(), masters.end(), c) != masters.end())
              continue;
            auto row = motion_row(boundary_dofs[c].component,
                                  rotation * (boundary_dofs[c].point - pivot));
            for (unsigned int j = dim; j < n_motions; ++j)
              row[j] /= size;
            for (const auto &e : basis)
              {
                double dot = 0;
                for (unsigned int j = 0; j < n_motions; ++j)
                  dot += row[j] * e[j];
                for (unsigned int j = 0; j < n_motions; ++j)
                  row[j] -= dot * e[j];
              }
            double norm = 0;
            for (const double v : row)
              norm += v * v;
            norm = std::sqrt(norm);
            if (norm > best_norm)
              best_norm = norm, best = c, best_residual = row;
          }
        if (!(best_norm > 1e-8))
          throw std::invalid_argument("Boundary conditions/Rigid: no set of nodes of boundary '" +
                                      load.boundary + "' determines its rigid motion");
        for (double &v : best_residual)
          v /= best_norm;
        basis.push_back(best_residual);
        masters.push_back(best);
      }
    FullMatrix<double> P(n_motions, n_motions);
    for (unsigned int m = 0; m < n_motions; ++m)
      {
        const auto &dof = boundary_dofs[masters[m]];
        const auto  row = motion_row(dof.component, rotation * (dof.point - pivot));
        for (unsigned int j = 0; j < n_motions; ++j)
          P(m, j) = row[j];
      }
    master_to_motion.reinit(n_motions, n_motions);
    master_to_motion.invert(P);
  }

  template <int dim>
  IndexSet RigidBoundary<dim>::master_candidates(const types::global_dof_index n_dofs) const
  {
    IndexSet set(n_dofs);
    for (const unsigned int c : candidates)
      set.add_index(boundary_dofs[c].index);
    return set;
  }

  template <int dim>
  IndexSet RigidBoundary<dim>::dofs(const types::global_dof_index n_dofs) const
  {
    IndexSet set(n_dofs);
    for (const auto &dof : boundary_dofs)
      set.add_index(dof.index);
    return set;
  }

  template <int dim>
  void RigidBoundary<dim>::add_constraints(AffineConstraints<double> &constraints,
                                           const bool                 for_sparsity) const
  {
    int conflict = 0;
    for (unsigned int s = 0; s < boundary_dofs.size(); ++s)
      {
        const auto &dof = boundary_dofs[s];
        if (!constraints.can_store_line(dof.index))
          continue;
        const bool is_master = for_sparsity ?
                                 std::find(candidates.begin(), candidates.end(), s) != candidates.end() :
                                 std::find(masters.begin(), masters.end(), s) != masters.end();
        if (constraints.is_constrained(dof.index))
          {
            conflict = 1; // a support got here first
            continue;
          }
        if (is_master)
          continue;
        constraints.add_line(dof.index);
        if (for_sparsity)
          {
            for (const unsigned int c : candidates)
              constraints.add_entry(dof.index, boundary_dofs[c].index, 1.);
            continue;
          }
        const auto row = motion_row(dof.component, rotation * (dof.point - pivot));
        for (unsigned int m = 0; m < n_motions; ++m)
          {
            double c = 0;
            for (unsigned int j = 0; j < n_motions; ++j)
              c += row[j] * master_to_motion(j, m);
            if (c != 0)
              constraints.add_entry(dof.index, boundary_dofs[masters[m]].index, c);
          }
      }
    if (Utilities::MPI::max(conflict, communicator) > 0)
      throw std::invalid_argument("Boundary conditions/Rigid: boundary '" + load.boundary +
                                  "' shares nodes with a supported (Clamped, Displacement, "
                                  "Rotation) or another rigid boundary; a rigid boundary must "
                                  "be free to move, name boundaries that do not touch");
  }

  template <int dim>
  void RigidBoundary<dim>::add_load(const double scale, const AffineConstraints<double> *constraints,
                                    PETScWrappers::MPI::Vector &rhs) const
  {
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    Vector<double> g(n_motions);
    for (unsigned int d = 0; d < dim; ++d)
      g(d) = scale * load.force[d];
    // The force acts at the load point, which turns with the boundary: about the pivot it adds
    // the moment r_u x F, r_u = R (center - pivot).
    Tensor<1, 3> r_u, F;
    const Tensor<1, dim> arm = rotation * (center - pivot);
    for (unsigned int d = 0; d < dim; ++d)
      r_u[d] = arm[d], F[d] = scale * load.force[d];
    const Tensor<1, 3> moment = scale * load.moment + cross_product_3d(r_u, F);
    if constexpr (dim == 2)
      g(2) = moment[2];
    else
      for (unsigned int d = 0; d < 3; ++d)
        g(3 + d) = moment[d];
    std::vector<types::global_dof_index> indices;
    Vector<double>                       f;
    if (constraints != nullptr)
      {
        // Condensed: the generalized force on the masters, (d motion / d master)^T g.
        f.reinit(n_motions);
        master_to_motion.Tvmult(f, g);
        for (const unsigned int m : masters)
          indices.push_back(boundary_dofs[m].index);
      }
    else
      {
        // Nodal forces on the candidates with resultant F and moment M about the centre, the
        // least-squares ones: f = P (P^T P)^-1 g.
        FullMatrix<double> P(candidates.size(), n_motions), PtP(n_motions, n_motions),
          PtP_inverse(n_motions, n_motions);
        for (unsigned int k = 0; k < candidates.size(); ++k)
          {
            const auto &dof = boundary_dofs[candidates[k]];
            const auto  row = motion_row(dof.component, rotation * (dof.point - pivot));
            for (unsigned int j = 0; j < n_motions; ++j)
              P(k, j) = row[j];
            indices.push_back(dof.index);
          }
        P.Tmmult(PtP, P);
        PtP_inverse.invert(PtP);
        Vector<double> y(n_motions);
        PtP_inverse.vmult(y, g);
        f.reinit(candidates.size());
        P.vmult(f, y);
      }
    rhs.add(indices, f);
  }

  template <int dim>
  void RigidBoundary<dim>::add_geometric_stiffness(const PETScWrappers::MPI::Vector &residual,
                                                   const double                      scale,
                                                   PETScWrappers::MPI::SparseMatrix &matrix) const
  {
    constexpr unsigned int n_rotations = n_motions - dim;
    std::vector<double>    sums(n_rotations * n_rotations + 1, 0.); // sum r_j f_k, then f . r
    for (const auto &dof : boundary_dofs)
      if (residual.in_local_range(dof.index))
        {
          const double         f = -residual[dof.index];
          const Tensor<1, dim> r = rotation * (dof.point - pivot);
          if constexpr (dim == 3)
            for (unsigned int j = 0; j < 3; ++j)
              sums[j * 3 + dof.component] += r[j] * f;
          sums.back() += f * r[dof.component];
        }
    MPI_Allreduce(MPI_IN_PLACE, sums.data(), sums.size(), MPI_DOUBLE, MPI_SUM, communicator);
    if (Utilities::MPI::this_mpi_process(communicator) != 0)
      return;
    // The applied force at the load point turns with the boundary too: its own term, with the
    // sign of an external force (f = -F at r_u).
    const Tensor<1, dim> r_u = rotation * (center - pivot);
    for (unsigned int k = 0; k < dim; ++k)
      {
        const double f = -scale * load.force[k];
        if constexpr (dim == 3)
          for (unsigned int j = 0; j < 3; ++j)
            sums[j * 3 + k] += r_u[j] * f;
        sums.back() += f * r_u[k];
      }
    FullMatrix<double> A(n_motions, n_motions), TtA(n_motions, n_motions), K(n_motions, n_motions);
    for (unsigned int j = 0; j < n_rotations; ++j)
      {
        for (unsigned int k = 0; k < n_rotations; ++k)
          A(dim + j, dim + k) = dim == 3 ? sums[j * 3 + k] : 0.;
        A(dim + j, dim + j) -= sums.back();
      }
    master_to_motion.Tmmult(TtA, A);
    TtA.mmult(K, master_to_motion);
    for (unsigned int a = 0; a < n_motions; ++a)
      for (unsigned int b = 0; b < n_motions; ++b)
        matrix.add(boundary_dofs[masters[a]].index, boundary_dofs[masters[b]].index, K(a, b));
  }

  template <int dim>
  void RigidBoundary<dim>::move(const PETScWrappers::MPI::Vector &du, const double alpha,
                                PETScWrappers::MPI::Vector &u) const
  {
    const auto     du_candidates = candidate_values(du);
    Vector<double> du_masters(n_motions), step(n_motions);
    for (unsigned int m = 0; m < n_motions; ++m)
      du_masters(m) = du_candidates[std::find(candidates.begin(), candidates.end(), masters[m]) -
                                    candidates.begin()];
    master_to_motion.vmult(step, du_masters);
    Tensor<1, 3> psi;
    Point<dim>   x_c = center_position;
    for (unsigned int d = 0; d < dim; ++d)
      x_c[d] += alpha * step(d);
    if constexpr (dim == 2)
      psi[2] = alpha * step(2);
    else
      for (unsigned int d = 0; d < 3; ++d)
        psi[d] = alpha * step(3 + d);
    const Tensor<2, dim> R = rotation_matrix<dim>(psi) * rotation;
    for (const auto &dof : boundary_dofs)
      if (u.in_local_range(dof.index))
        {
          const Point<dim> x = x_c + R * (dof.point - pivot);
          u(dof.index)       = x[dof.component] - dof.point[dof.component];
        }
    u.compress(VectorOperation::insert);
  }

  template <int dim>
  typename RigidBoundary<dim>::Motion
  RigidBoundary<dim>::motion(const PETScWrappers::MPI::Vector &u, const bool geometrically_nonlinear) const
  {
    Motion     result;
    const auto values = candidate_values(u);
    if (!geometrically_nonlinear)
      {
        // The linear problem's constraints hold the reference linearisation: (U, psi) = T u_m.
        Vector<double> u_masters(n_motions), q(n_motions);
        for (unsigned int m = 0; m < n_motions; ++m)
          u_masters(m) = values[std::find(candidates.begin(), candidates.end(), masters[m]) -
                                candidates.begin()];
        master_to_motion.vmult(q, u_masters);
        for (unsigned int j = dim; j < n_motions; ++j)
          result.rotation[dim == 2 ? 2 : j - dim] = q(j);
        // The load point's displacement: the pivot's plus psi x (center - pivot).
        Tensor<1, 3> r3;
        for (unsigned int d = 0; d < dim; ++d)
          r3[d] = center[d] - pivot[d];
        const Tensor<1, 3> turn = cross_product_3d(result.rotation, r3);
        for (unsigned int d = 0; d < dim; ++d)
          result.displacement[d] = q(d) + turn[d];
        return result;
      }
    Tensor<2, dim> R;
    Point<dim>     x_c;
    frame_from(values, R, x_c);
    result.displacement = (x_c + R * (center - pivot)) - center;
    if constexpr (dim == 2)
      {
        const double angle = std::atan2(R[1][0], R[0][0]);
        last_angle += std::remainder(angle - last_angle, 2 * M_PI);
        result.rotation[2] = last_angle;
      }
    else
      {
        const double c     = std::clamp((trace(R) - 1) / 2, -1., 1.);
        const double angle = std::acos(c);
        const Tensor<1, 3> axial({R[2][1] - R[1][2], R[0][2] - R[2][0], R[1][0] - R[0][1]});
        result.rotation = angle < 1e-12 ? axial / 2 : axial * (angle / (2 * std::sin(angle)));
        // The same rotation about the opposite axis, or a further turn, as the vector nearest
        // the previous one: rotations past half a turn stay continuous.
        const double length = result.rotation.norm();
        if (length > 0)
          {
            const Tensor<1, 3> axis = result.rotation / length;
            Tensor<1, 3>       best = result.rotation;
            for (int turns = -2; turns <= 2; ++turns)
              {
                const Tensor<1, 3> candidate = result.rotation + (2 * M_PI * turns) * axis;
                if ((candidate - last_rotation).norm() < (best - last_rotation).norm())
                  best = candidate;
              }
            result.rotation = best;
          }
        last_rotation = result.rotation;
      }
    return result;
  }

  template class RigidBoundary<2>;
  template class RigidBoundary<3>;
} // namespace compliant
