#include "constraints/rigid_motion_check.h"

#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    struct PlacedDof
    {
      Point<3>     position;
      unsigned int component;
    };

    // Positions of the displacement DoFs in `wanted`, from the cells this rank holds: locally
    // owned first, the others (ghost, or all of a shared mesh) only for DoFs still missing.
    template <int dim>
    std::map<types::global_dof_index, PlacedDof>
    place_dofs(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
               const std::set<types::global_dof_index> &wanted)
    {
      const FiniteElement<dim> &fe   = dof_handler.get_fe();
      const unsigned int        base = fe.component_to_base_index(0).first;
      const Quadrature<dim>     support_points(fe.base_element(base).get_unit_support_points());
      FEValues<dim>             values(mapping, fe, support_points, update_quadrature_points);
      std::vector<types::global_dof_index>          indices(fe.n_dofs_per_cell());
      std::map<types::global_dof_index, PlacedDof> placed;
      for (const bool owned_pass : {true, false})
        for (const auto &cell : dof_handler.active_cell_iterators())
          {
            if (cell->is_artificial() || cell->is_locally_owned() != owned_pass)
              continue;
            cell->get_dof_indices(indices);
            bool needed = false;
            for (const auto i : indices)
              needed = needed || (wanted.count(i) > 0 && placed.count(i) == 0);
            if (!needed)
              continue;
            values.reinit(cell);
            for (unsigned int i = 0; i < indices.size(); ++i)
              {
                const auto [base_and_copy, index_in_base] = fe.system_to_base_index(i);
                const unsigned int component              = fe.system_to_component_index(i).first;
                if (component >= dim || base_and_copy.first != base || wanted.count(indices[i]) == 0)
                  continue;
                PlacedDof dof{Point<3>(), component};
                for (unsigned int d = 0; d < dim; ++d)
                  dof.position[d] = values.quadrature_point(index_in_base)[d];
                placed.emplace(indices[i], dof);
              }
          }
      return placed;
    }

    // Rigid motion m at a DoF: translations first, then rotations about the centre with unit
    // amplitude at distance `size` (so both kinds weigh alike).
    template <int dim>
    double mode_value(unsigned int m, const PlacedDof &dof, const Point<3> &centre, double size)
    {
      if (m < dim)
        return m == dof.component ? 1. : 0.;
      const Tensor<1, 3> r     = (dof.position - centre) / size;
      Tensor<1, 3>       axis;
      axis[dim == 2 ? 2 : m - dim] = 1;
      return cross_product_3d(axis, r)[dof.component];
    }

    std::string format_vector(const Tensor<1, 3> &v, unsigned int n)
    {
      std::ostringstream s;
      s << std::setprecision(4) << '(';
      for (unsigned int d = 0; d < n; ++d)
        s << (d ? ", " : "") << (std::abs(v[d]) < 1e-12 ? 0. : v[d]);
      s << ')';
      return s.str();
    }

    // 'x' for a coordinate axis, else the unit vector.
    std::string format_direction(Tensor<1, 3> v, unsigned int n)
    {
      v /= v.norm();
      for (unsigned int d = 0; d < n; ++d)
        if (std::abs(std::abs(v[d]) - 1) < 1e-6)
          return std::string(1, "xyz"[d]);
      return format_vector(v, n);
    }

    // The free motions: an orthonormal basis of the Gram matrix's null space, the free translations
    // named first, then each remaining motion as a rotation about its axis.
    template <int dim>
    std::vector<std::string> name_free_motions(const FullMatrix<double> &gram, const Point<3> &centre,
                                               double size)
    {
      constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
      // Exact zero for a free motion, up to round-off; a held one is at least of the order of the
      // held DoFs' squared lever arms over the part's size (1e-8: a pad 1e-4 of the size).
      const double threshold = 1e-8;
      LAPACKFullMatrix<double> translations(dim, dim), all(n_modes, n_modes);
      for (unsigned int i = 0; i < n_modes; ++i)
        for (unsigned int j = 0; j < n_modes; ++j)
          {
            all(i, j) = gram(i, j);
            if (i < dim && j < dim)
              translations(i, j) = gram(i, j);
          }
      std::vector<std::string> names;
      std::vector<Vector<double>> free_translations;
      {
        Vector<double>           eigenvalues;
        FullMatrix<double>       vectors;
        translations.compute_eigenvalues_symmetric(-1, threshold, 0, eigenvalues, vectors);
        for (unsigned int k = 0; k < eigenvalues.size(); ++k)
          {
            Tensor<1, 3>   direction;
            Vector<double> motion(n_modes);
            for (unsigned int d = 0; d < dim; ++d)
              direction[d] = motion[d] = vectors(d, k);
            names.push_back("translation along " + format_direction(direction, dim));
            free_translations.push_back(motion);
          }
      }
      Vector<double>     eigenvalues;
      FullMatrix<double> vectors;
      all.compute_eigenvalues_symmetric(-1, threshold, 0, eigenvalues, vectors);
      // Rotations: the null vectors with their free-translation part removed, orthonormalised.
      std::vector<Vector<double>> basis = free_translations;
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        {
          Vector<double> motion(n_modes);
          for (unsigned int i = 0; i < n_modes; ++i)
            motion[i] = vectors(i, k);
          for (const auto &b : basis)
            motion.add(-(motion * b), b);
          if (motion.l2_norm() < 1e-6)
            continue;
          motion /= motion.l2_norm();
          basis.push_back(motion);
          Tensor<1, 3> omega, t;
          for (unsigned int d = 0; d < dim; ++d)
            t[d] = motion[d];
          for (unsigned int a = 0; a < (dim == 2 ? 1u : 3u); ++a)
            omega[dim == 2 ? 2 : a] = motion[dim + a] / size;
          // u = t + omega x (x - centre): the axis passes through centre + omega x t / |omega|^2.
          const Point<3> on_axis = centre + cross_product_3d(omega, t) / omega.norm_square();
          names.push_back(dim == 2 ? "rotation about " + format_vector(on_axis, 2) :
                                     "rotation about " + format_direction(omega, 3) + " through " +
                                       format_vector(on_axis, 3));
        }
      return names;
    }
  } // namespace

  std::string FreeRigidMotions::describe() const
  {
    std::string text;
    for (unsigned int i = 0; i < motions.size(); ++i)
      text += (i == 0 ? "" : i + 1 == motions.size() ? " and " : ", ") + motions[i];
    return text;
  }

  template <int dim>
  FreeRigidMotions free_rigid_motions(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
                                      const AffineConstraints<double> &constraints,
                                      const IndexSet                  &follow_rigid_motions)
  {
    constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
    const MPI_Comm         comm    = dof_handler.get_communicator();
    const IndexSet        &owned   = dof_handler.locally_owned_dofs();

    std::set<types::global_dof_index> wanted;
    const auto checked = [&](const types::global_dof_index i) {
      return owned.is_element(i) && !follow_rigid_motions.is_element(i);
    };
    for (const auto &line : constraints.get_lines())
      if (checked(line.index))
        {
          wanted.insert(line.index);
          for (const auto &entry : line.entries)
            wanted.insert(entry.first);
        }
    const auto placed = place_dofs(mapping, dof_handler, wanted);

    // The centre and size of the part, from the vertices of the locally owned cells.
    Tensor<1, 4> sums;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          {
            for (unsigned int d = 0; d < dim; ++d)
              sums[d] += cell->vertex(v)[d];
            sums[3] += 1;
          }
    sums = Utilities::MPI::sum(sums, comm);
    Point<3> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = sums[d] / std::max(sums[3], 1.);
    double size = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto v : cell->vertex_indices())
          {
            Point<3> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = cell->vertex(v)[d];
            size = std::max(size, p.distance(centre));
          }
    size = std::max(Utilities::MPI::max(size, comm), std::numeric_limits<double>::min());

    // Gram matrix of each motion's violation of the lines: u_i - sum_j a_ij u_j.
    FullMatrix<double> gram(n_modes, n_modes);
    int                undecided = 0;
    for (const auto &line : constraints.get_lines())
      {
        if (!checked(line.index))
          continue;
        const auto dof = placed.find(line.index);
        if (dof == placed.end())
          continue; // a pressure DoF
        double violation[n_modes];
        for (unsigned int m = 0; m < n_modes; ++m)
          violation[m] = mode_value<dim>(m, dof->second, centre, size);
        for (const auto &[index, weight] : line.entries)
          {
            const auto master = placed.find(index);
            if (master == placed.end())
              {
                undecided = 1;
                break;
              }
            for (unsigned int m = 0; m < n_modes; ++m)
              violation[m] -= weight * mode_value<dim>(m, master->second, centre, size);
          }
        for (unsigned int i = 0; i < n_modes; ++i)
          for (unsigned int j = 0; j < n_modes; ++j)
            gram(i, j) += violation[i] * violation[j];
      }
    FreeRigidMotions result;
    result.decided = Utilities::MPI::max(undecided, comm) == 0;
    Utilities::MPI::sum(gram, comm, gram);
    if (result.decided)
      result.motions = name_free_motions<dim>(gram, centre, size);
    return result;
  }

  template <int dim>
  void require_rigid_motion_held(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
                                 const AffineConstraints<double> &constraints,
                                 const std::vector<RigidBoundary<dim>> &rigid_boundaries, const std::string &what)
  {
    IndexSet rigid_dofs(dof_handler.n_dofs());
    for (const auto &rigid : rigid_boundaries)
      rigid_dofs.add_indices(rigid.dofs(dof_handler.n_dofs()));
    const FreeRigidMotions free = free_rigid_motions(mapping, dof_handler, constraints, rigid_dofs);
    if (!free.any())
      return;
    throw std::invalid_argument(
      "Boundary conditions: the supports leave " +
      (free.motions.size() == 1 ? std::string("a rigid-body motion") :
                                  std::to_string(free.motions.size()) + " rigid-body motions") +
      " free (" + free.describe() + "): the part is a mechanism and " + what +
      " has no unique answer; hold those motions too (Clamped, more components in Displacement, or a "
      "support on another boundary)");
  }

  template FreeRigidMotions free_rigid_motions<2>(const Mapping<2> &, const DoFHandler<2> &,
                                                  const AffineConstraints<double> &, const IndexSet &);
  template FreeRigidMotions free_rigid_motions<3>(const Mapping<3> &, const DoFHandler<3> &,
                                                  const AffineConstraints<double> &, const IndexSet &);
  template void require_rigid_motion_held<2>(const Mapping<2> &, const DoFHandler<2> &, const AffineConstraints<double> &,
                                             const std::vector<RigidBoundary<2>> &, const std::string &);
  template void require_rigid_motion_held<3>(const Mapping<3> &, const DoFHandler<3> &, const AffineConstraints<double> &,
                                             const std::vector<RigidBoundary<3>> &, const std::string &);
} // namespace compliant
