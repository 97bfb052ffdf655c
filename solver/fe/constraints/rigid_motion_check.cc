#include "constraints/rigid_motion_check.h"

#include "linear_algebra/rigid_body_modes.h"

#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
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
      unsigned int body;
    };

    // The separate bodies of the mesh (cells joined through shared vertices), with the centre and
    // size of each; one body (the whole part) where this rank does not hold every cell.
    struct Bodies
    {
      std::vector<unsigned int> of_cell; // by active cell index; empty: one body
      std::vector<Point<3>>     centre;
      std::vector<double>       size;
      unsigned int              n() const { return centre.size(); }
    };

    // A free motion's eigenvalue of the Gram matrix is zero up to round-off (a few eps times its
    // trace); a held one is about the sum of the held DoFs' squared lever arms over the body's size
    // squared, so 1e-12 of the trace lets a pad of 1e-6 of the size hold a part of 1e6 DoFs.
    constexpr double free_fraction_of_trace = 1e-12;

    // Beyond this, the bodies' motions are tested together (the Gram matrix has 6 rows per body).
    constexpr unsigned int max_bodies = 100;

    // Union-find over the vertices of every cell: bodies numbered by their first cell, so alike on
    // every rank.
    template <int dim>
    std::vector<unsigned int> label_bodies(const Triangulation<dim> &mesh, const std::vector<int> &joining,
                                           unsigned int &n_bodies)
    {
      std::vector<unsigned int> parent(mesh.n_vertices());
      std::iota(parent.begin(), parent.end(), 0u);
      const auto root = [&](unsigned int v) {
        while (parent[v] != v)
          v = parent[v] = parent[parent[v]];
        return v;
      };
      for (const auto &cell : mesh.active_cell_iterators())
        for (const auto v : cell->vertex_indices())
          parent[root(cell->vertex_index(v))] = root(cell->vertex_index(0));
      // A rigid boundary makes every body it touches one rigid piece.
      for (const int id : joining)
        {
          int first = -1;
          for (const auto &cell : mesh.active_cell_iterators())
            for (const auto f : cell->face_indices())
              if (cell->face(f)->at_boundary() && static_cast<int>(cell->face(f)->boundary_id()) == id)
                {
                  const unsigned int v = cell->face(f)->vertex_index(0);
                  if (first < 0)
                    first = static_cast<int>(v);
                  parent[root(v)] = root(static_cast<unsigned int>(first));
                }
        }
      std::map<unsigned int, unsigned int> number;
      std::vector<unsigned int>            of_cell(mesh.n_active_cells());
      for (const auto &cell : mesh.active_cell_iterators())
        of_cell[cell->active_cell_index()] =
          number.emplace(root(cell->vertex_index(0)), number.size()).first->second;
      n_bodies = number.size();
      return of_cell;
    }

    template <int dim>
    Bodies find_bodies(const Triangulation<dim> &mesh, const std::vector<int> &joining, MPI_Comm comm)
    {
      bool whole = true;
      for (const auto &cell : mesh.active_cell_iterators())
        whole = whole && !cell->is_artificial();
      whole = Utilities::MPI::min(whole ? 1 : 0, comm) == 1;
      Bodies       bodies;
      unsigned int n = 1;
      if (whole)
        bodies.of_cell = label_bodies(mesh, joining, n);
      if (n > max_bodies)
        {
          bodies.of_cell.clear();
          n = 1;
        }
      // Centres and sizes from the vertices: of every cell where each rank has them all.
      const auto body_of = [&](const auto &cell) {
        return bodies.of_cell.empty() ? 0u : bodies.of_cell[cell->active_cell_index()];
      };
      const auto counted = [&](const auto &cell) { return whole ? true : cell->is_locally_owned(); };
      std::vector<double> sums(4 * n, 0.);
      for (const auto &cell : mesh.active_cell_iterators())
        if (counted(cell))
          for (const auto v : cell->vertex_indices())
            {
              for (unsigned int d = 0; d < dim; ++d)
                sums[4 * body_of(cell) + d] += cell->vertex(v)[d];
              sums[4 * body_of(cell) + 3] += 1;
            }
      if (!whole)
        for (auto &x : sums)
          x = Utilities::MPI::sum(x, comm);
      bodies.centre.resize(n);
      bodies.size.assign(n, 0.);
      for (unsigned int b = 0; b < n; ++b)
        for (unsigned int d = 0; d < dim; ++d)
          bodies.centre[b][d] = sums[4 * b + d] / std::max(sums[4 * b + 3], 1.);
      for (const auto &cell : mesh.active_cell_iterators())
        if (counted(cell))
          for (const auto v : cell->vertex_indices())
            {
              Point<3> p;
              for (unsigned int d = 0; d < dim; ++d)
                p[d] = cell->vertex(v)[d];
              auto &size = bodies.size[body_of(cell)];
              size       = std::max(size, p.distance(bodies.centre[body_of(cell)]));
            }
      for (auto &size : bodies.size)
        size = std::max(whole ? size : Utilities::MPI::max(size, comm), std::numeric_limits<double>::min());
      return bodies;
    }

    // Positions of the displacement DoFs in `wanted`, from the cells this rank holds: locally
    // owned first, the others (ghost, or all of a shared mesh) only for DoFs still missing.
    template <int dim>
    std::map<types::global_dof_index, PlacedDof>
    place_dofs(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
               const std::set<types::global_dof_index> &wanted, const Bodies &bodies)
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
            if (placed.size() == wanted.size())
              return placed; // the second pass, over other ranks' cells, only for what is missing
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
                PlacedDof dof{Point<3>(), component,
                              bodies.of_cell.empty() ? 0u : bodies.of_cell[cell->active_cell_index()]};
                for (unsigned int d = 0; d < dim; ++d)
                  dof.position[d] = values.quadrature_point(index_in_base)[d];
                placed.emplace(indices[i], dof);
              }
          }
      return placed;
    }

    // Rigid motion m of the DoF's body at the DoF: translations first, then rotations about the
    // body's centre with unit amplitude at distance `size` (so both kinds weigh alike).
    template <int dim>
    double mode_value(unsigned int m, const PlacedDof &dof, const Bodies &bodies)
    {
      Tensor<1, dim> r;
      for (unsigned int d = 0; d < dim; ++d)
        r[d] = (dof.position[d] - bodies.centre[dof.body][d]) / bodies.size[dof.body];
      return rigid_body_mode_value<dim>(m, dof.component, r);
    }

    // Components below 1e-9 of `scale` (a body's size: round-off off an axis) print as 0.
    std::string format_vector(const Tensor<1, 3> &v, unsigned int n, double scale = 0)
    {
      std::ostringstream s;
      s << std::setprecision(4) << '(';
      for (unsigned int d = 0; d < n; ++d)
        s << (d ? ", " : "") << (std::abs(v[d]) < 1e-9 * std::max(scale, v.norm()) ? 0. : v[d]);
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
                                               double size, double threshold)
    {
      constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
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
          if (omega.norm() * size < 1e-6)
            continue; // a translation the translation block alone did not see as free
          // u = t + omega x (x - centre): the axis passes through centre + omega x t / |omega|^2.
          const Point<3> on_axis = centre + cross_product_3d(omega, t) / omega.norm_square();
          names.push_back(dim == 2 ? "rotation about " + format_vector(on_axis, 2, size + centre.norm()) :
                                     "rotation about " + format_direction(omega, 3) + " through " +
                                       format_vector(on_axis, 3, size + centre.norm()));
        }
      return names;
    }
    // Each body's own free motions (the others held still), named; then the number of free
    // motions that move several bodies together (bodies tied to each other but to nothing else).
    template <int dim>
    void name_free_motions_of_bodies(const FullMatrix<double> &gram, const Bodies &bodies,
                                     FreeRigidMotions &result)
    {
      constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
      const unsigned int     n       = gram.m();
      LAPACKFullMatrix<double> all(n, n);
      all = gram;
      Vector<double>     eigenvalues;
      FullMatrix<double> vectors;
      double trace = 0;
      for (unsigned int i = 0; i < n; ++i)
        trace += gram(i, i);
      const double threshold = std::max(free_fraction_of_trace * trace, std::numeric_limits<double>::min());
      all.compute_eigenvalues_symmetric(-1, threshold, 0, eigenvalues, vectors);
      result.count    = eigenvalues.size();
      result.n_bodies = bodies.n();
      if (result.count == 0)
        return;
      unsigned int single = 0; // free motions of one body alone
      for (unsigned int b = 0; b < bodies.n(); ++b)
        {
          FullMatrix<double> block(n_modes, n_modes);
          for (unsigned int i = 0; i < n_modes; ++i)
            for (unsigned int j = 0; j < n_modes; ++j)
              block(i, j) = gram(n_modes * b + i, n_modes * b + j);
          const auto names = name_free_motions<dim>(block, bodies.centre[b], bodies.size[b], threshold);
          if (bodies.n() == 1)
            result.motions = names;
          else if (!names.empty())
            {
              std::string text = "body " + std::to_string(b + 1) + " of " + std::to_string(bodies.n()) +
                                 " (centre " + format_vector(bodies.centre[b], dim) + "): ";
              if (names.size() == n_modes)
                text += "held by nothing";
              else
                for (unsigned int k = 0; k < names.size(); ++k)
                  text += (k ? ", " : "") + names[k];
              result.motions.push_back(text);
            }
          single += names.size();
        }
      if (single < result.count)
        result.motions.push_back(std::to_string(result.count - single) + " motion(s) of several bodies together");
    }
  } // namespace

  std::string FreeRigidMotions::describe() const
  {
    std::string text;
    for (unsigned int i = 0; i < motions.size(); ++i)
      text += (i == 0 ? "" : n_bodies > 1 ? "; " : i + 1 == motions.size() ? " and " : ", ") + motions[i];
    return text;
  }

  template <int dim>
  FreeRigidMotions free_rigid_motions(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
                                      const AffineConstraints<double> &constraints,
                                      const IndexSet                  &follow_rigid_motions,
                                      const std::vector<int>          &joining_boundaries)
  {
    constexpr unsigned int n_modes = dim == 2 ? 3 : 6;
    const MPI_Comm         comm    = dof_handler.get_communicator();
    const IndexSet        &owned   = dof_handler.locally_owned_dofs();

    // Every owned line, its DoF and its masters. A rigid boundary's own lines hold no motion of the
    // piece it joins; only where one names a master this rank cannot place is it left out.
    std::set<types::global_dof_index> wanted;
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          wanted.insert(line.index);
          for (const auto &entry : line.entries)
            wanted.insert(entry.first);
        }
    const Bodies bodies = find_bodies(dof_handler.get_triangulation(), joining_boundaries, comm);
    const auto   placed = place_dofs(mapping, dof_handler, wanted, bodies);

    // Gram matrix of each motion's violation of the lines, u_i - sum_j a_ij u_j, over the
    // motions of every body (n_modes rows each).
    FullMatrix<double>        gram(n_modes * bodies.n(), n_modes * bodies.n());
    std::vector<double>       violation(n_modes * bodies.n());
    std::vector<unsigned int> touched; // bodies the line names
    int                       undecided = 0;
    for (const auto &line : constraints.get_lines())
      {
        const auto dof = placed.find(line.index);
        if (!owned.is_element(line.index) || dof == placed.end())
          continue; // a pressure DoF
        bool complete = true;
        for (const auto &entry : line.entries)
          complete = complete && placed.count(entry.first) > 0;
        if (!complete)
          {
            undecided = undecided || !follow_rigid_motions.is_element(line.index);
            continue;
          }
        for (const unsigned int b : touched)
          std::fill(violation.begin() + n_modes * b, violation.begin() + n_modes * (b + 1), 0.);
        touched.assign(1, dof->second.body);
        for (unsigned int m = 0; m < n_modes; ++m)
          violation[n_modes * dof->second.body + m] = mode_value<dim>(m, dof->second, bodies);
        for (const auto &[index, weight] : line.entries)
          {
            const PlacedDof &master = placed.at(index);
            if (std::find(touched.begin(), touched.end(), master.body) == touched.end())
              touched.push_back(master.body);
            for (unsigned int m = 0; m < n_modes; ++m)
              violation[n_modes * master.body + m] -= weight * mode_value<dim>(m, master, bodies);
          }
        for (const unsigned int a : touched)
          for (const unsigned int b : touched)
            for (unsigned int i = n_modes * a; i < n_modes * (a + 1); ++i)
              for (unsigned int j = n_modes * b; j < n_modes * (b + 1); ++j)
                gram(i, j) += violation[i] * violation[j];
      }
    FreeRigidMotions result;
    result.decided = Utilities::MPI::max(undecided, comm) == 0;
    Utilities::MPI::sum(gram, comm, gram);
    if (result.decided)
      name_free_motions_of_bodies<dim>(gram, bodies, result);
    return result;
  }

  template <int dim>
  void require_rigid_motion_held(const Mapping<dim> &mapping, const DoFHandler<dim> &dof_handler,
                                 const AffineConstraints<double> &constraints,
                                 const std::vector<RigidBoundary<dim>> &rigid_boundaries, const std::string &what)
  {
    IndexSet         rigid_dofs(dof_handler.n_dofs());
    std::vector<int> rigid_ids;
    for (const auto &rigid : rigid_boundaries)
      {
        rigid_dofs.add_indices(rigid.dofs(dof_handler.n_dofs()));
        rigid_ids.push_back(rigid.load.boundary_id);
      }
    const FreeRigidMotions free = free_rigid_motions(mapping, dof_handler, constraints, rigid_dofs, rigid_ids);
    if (!free.any())
      return;
    throw std::invalid_argument(
      "Boundary conditions: the supports leave " +
      (free.count == 1 ? std::string("a rigid-body motion") : std::to_string(free.count) + " rigid-body motions") +
      " free (" + free.describe() + "): the part is a mechanism and " + what +
      " has no unique answer; hold those motions too (Clamped, more components in Displacement, or a "
      "support on another boundary)" +
      (free.n_bodies > 1 ? ". The mesh is " + std::to_string(free.n_bodies) +
                             " bodies that share no nodes: glue volumes meant to be one part (gmsh "
                             "BooleanFragments or Coherence), or tie or support each body" :
                           std::string()));
  }

  template FreeRigidMotions free_rigid_motions<2>(const Mapping<2> &, const DoFHandler<2> &,
                                                  const AffineConstraints<double> &, const IndexSet &,
                                                  const std::vector<int> &);
  template FreeRigidMotions free_rigid_motions<3>(const Mapping<3> &, const DoFHandler<3> &,
                                                  const AffineConstraints<double> &, const IndexSet &,
                                                  const std::vector<int> &);
  template void require_rigid_motion_held<2>(const Mapping<2> &, const DoFHandler<2> &, const AffineConstraints<double> &,
                                             const std::vector<RigidBoundary<2>> &, const std::string &);
  template void require_rigid_motion_held<3>(const Mapping<3> &, const DoFHandler<3> &, const AffineConstraints<double> &,
                                             const std::vector<RigidBoundary<3>> &, const std::string &);
} // namespace compliant
