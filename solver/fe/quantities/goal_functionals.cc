#include "quantities/goal_functionals.h"

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

#include "quantities/named_points.h"
#include "quantities/point_location.h"
#include "quantities/reaction_weights.h"

#include <array>
#include <cmath>
#include <optional>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    const char *axis_names[3] = {"x", "y", "z"};

    // What a goal functional integrates: sum_c weight[c] v_c (a displacement) or
    // sum_ij weights[i][j] sigma_ij(v) (a stress, sigma_zz of 2D models included), under the bump
    // around `centre`, or over boundary `boundary_id` when that is set: averaged over it, or with
    // `rigid_fit`, sum_c (g . R_c(x)) v_c integrated (a best-fit rotation, reaction_weights.h).
    struct Integrand
    {
      Tensor<1, 3>          displacement_weights;
      SymmetricTensor<2, 3> stress_weights;
      Point<3>              centre;
      int                   boundary_id = -1;
      bool                  rigid_fit   = false;
      std::array<double, 6> g{};
    };

    bool strip_prefix(std::string &text, const std::string &prefix)
    {
      if (text.rfind(prefix, 0) != 0)
        return false;
      text.erase(0, prefix.size());
      return true;
    }

    bool strip_suffix(std::string &text, const std::string &suffix)
    {
      if (text.size() <= suffix.size() || text.compare(text.size() - suffix.size(), suffix.size(), suffix) != 0)
        return false;
      text.erase(text.size() - suffix.size());
      return true;
    }

    template <int dim>
    Point<3> to_3d(const Point<dim> &p)
    {
      Point<3> q;
      for (unsigned int d = 0; d < dim; ++d)
        q[d] = p[d];
      return q;
    }

    // The integrand of quantity `name`, if it is one of the known linear functionals.
    template <int dim>
    std::optional<Integrand> integrand_of(const LinearElasticProblem<dim> &problem, const std::string &name,
                                          const Quantities &values)
    {
      const auto &p = problem.parameters;
      Integrand   integrand;
      if (rotation_weights(problem, name, integrand.g, integrand.boundary_id))
        {
          integrand.rigid_fit = true;
          return integrand;
        }
      std::string rest = name;
      for (unsigned int c = 0; c < dim; ++c)
        {
          std::string point = rest;
          if (strip_prefix(point, "displacement_") && strip_suffix(point, std::string("_") + axis_names[c]))
            for (const auto &[n, x] : parse_named_points<dim>(p.points, p.geometry_parameters, "Quantities/Points"))
              if (n == point)
                {
                  integrand.displacement_weights[c] = 1;
                  integrand.centre                  = to_3d(x);
                  return integrand;
                }
          std::string boundary = rest;
          if (strip_prefix(boundary, "mean_displacement_") && strip_suffix(boundary, std::string("_") + axis_names[c]))
            if (const auto id = problem.geometry.boundary_ids.find(boundary); id != problem.geometry.boundary_ids.end())
              {
                integrand.displacement_weights[c] = 1;
                integrand.boundary_id             = id->second;
                return integrand;
              }
        }
      strip_suffix(rest, "_raw"); // the raw stress: the same functional, regularized
      const auto stress_points = parse_named_points<dim>(p.stress_points, p.geometry_parameters, "Quantities/Stress points");
      const char *components[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};
      const unsigned int index[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      for (const auto &[point, x] : stress_points)
        {
          integrand.centre = to_3d(x);
          for (unsigned int k = 0; k < (dim == 2 ? 4u : 6u); ++k)
            if (rest == "stress_" + point + "_" + components[k])
              {
                // sigma_xy = W : sigma with W_xy = W_yx = 1/2
                integrand.stress_weights[index[k][0]][index[k][1]] = index[k][0] == index[k][1] ? 1 : 0.5;
                return integrand;
              }
          if (rest == "von_mises_" + point)
            {
              // d sigma_vm = 3 s : d sigma / (2 sigma_vm), s the deviator at the computed stress.
              SymmetricTensor<2, 3> sigma;
              for (unsigned int k = 0; k < (dim == 2 ? 4u : 6u); ++k)
                {
                  const auto found = values.find("stress_" + point + "_" + components[k]);
                  if (found == values.end())
                    return std::nullopt;
                  sigma[index[k][0]][index[k][1]] = found->second;
                }
              const double vm = std::sqrt(1.5 * deviator(sigma) * deviator(sigma));
              if (!(vm > 0))
                return std::nullopt;
              integrand.stress_weights = 1.5 / vm * deviator(sigma);
              return integrand;
            }
        }
      return std::nullopt;
    }

    // Half the diameter of the coarse cell around the point (the same on every rung of a ladder).
    template <int dim>
    double coarse_radius(const LinearElasticProblem<dim> &problem, const Point<3> &centre)
    {
      Point<dim> x;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] = centre[d];
      const auto found = owned_cell_around(*problem.mapping, problem.dof_handler, x);
      double     r     = 0;
      if (found.first.state() == IteratorState::valid)
        {
          typename Triangulation<dim>::cell_iterator coarse = found.first;
          while (coarse->level() > 0)
            coarse = coarse->parent();
          r = 0.5 * coarse->diameter();
        }
      return Utilities::MPI::max(r, problem.communicator);
    }

    // j_i = a(phi_i, psi_h) for a reaction q(v) = sum_i psi_i r_i(v) = a(v, psi_h) on the dual's
    // space; psi_h is psi made conforming across hanging nodes, kept as the lifting.
    template <int dim>
    void assemble_reaction_functional(const LinearElasticProblem<dim> &problem, PETScWrappers::MPI::Vector &psi,
                                      const AffineConstraints<double> &homogeneous, PETScWrappers::MPI::Vector &j)
    {
      problem.hanging_node_constraints.distribute(psi);
      PETScWrappers::MPI::Vector psi_h(problem.locally_owned_dofs, problem.locally_relevant_dofs, problem.communicator);
      psi_h = psi;
      const auto   &fe = *problem.fe;
      FEValues<dim> fe_values(*problem.mapping, fe, *problem.quadrature, update_gradients | update_JxW_values);
      const FEValuesExtractors::Vector     u(0);
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      std::vector<Tensor<2, dim>>          grad(fe_values.n_quadrature_points);
      Vector<double>                       cell_j(fe.n_dofs_per_cell());
      j.reinit(problem.locally_owned_dofs, problem.communicator);
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values[u].get_function_gradients(psi_h, grad);
            double nonzero = 0;
            for (const auto &g : grad)
              nonzero += g.norm();
            if (nonzero == 0)
              continue; // psi lives on the boundary's layer of cells only
            const Material &material = problem.materials.at(cell->material_id());
            cell_j                   = 0;
            for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
              {
                double     sigma_zz;
                const auto sigma = problem.cauchy_stress(grad[q], material, 0, sigma_zz);
                for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                  cell_j(i) += (sigma * fe_values[u].symmetric_gradient(i, q)) * fe_values.JxW(q) * problem.thickness;
              }
            cell->get_dof_indices(dofs);
            homogeneous.distribute_local_to_global(cell_j, dofs, j);
          }
      j.compress(VectorOperation::add);
    }
  } // namespace

  template <int dim>
  bool assemble_goal_functional(const LinearElasticProblem<dim> &problem, const std::string &name,
                                const Quantities &values, const AffineConstraints<double> &homogeneous,
                                PETScWrappers::MPI::Vector &j, PETScWrappers::MPI::Vector &lifting, double radius)
  {
    if (problem.mixed)
      return false;
    lifting.clear();
    if (reaction_weights(problem, name, lifting))
      {
        assemble_reaction_functional(problem, lifting, homogeneous, j);
        return true;
      }
    const auto integrand = integrand_of(problem, name, values);
    if (!integrand)
      return false;
    const bool on_boundary = integrand->boundary_id >= 0;
    if (!on_boundary && radius <= 0)
      radius = coarse_radius(problem, integrand->centre);
    if (!on_boundary && !(radius > 0))
      return false; // the point lies in no cell
    const auto &fe = *problem.fe;
    // The bump's integral, then j over the cells it touches: two passes over the same points.
    const auto weight = [&](const Point<dim> &x) {
      if (on_boundary)
        return 1.0;
      double r2 = 0;
      for (unsigned int d = 0; d < dim; ++d)
        r2 += (x[d] - integrand->centre[d]) * (x[d] - integrand->centre[d]);
      const double s = 1 - r2 / (radius * radius);
      return s > 0 ? s * s : 0.0;
    };
    const UpdateFlags flags = update_values | update_gradients | update_quadrature_points | update_JxW_values;
    FEValues<dim>     fe_values(*problem.mapping, fe, *problem.quadrature, flags);
    FEFaceValues<dim> fe_face_values(*problem.mapping, fe, *problem.face_quadrature, flags);
    std::vector<types::global_dof_index> dof_indices(fe.n_dofs_per_cell());
    Vector<double>                       cell_j(fe.n_dofs_per_cell());
    double                               total = 0;
    Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = integrand->centre[d];
    // Adds the points of one cell (or face) to the bump's integral, or their share to cell_j.
    const auto add_points = [&](const FEValuesBase<dim> &v, const Material &material, const bool assemble) {
      for (unsigned int q = 0; q < v.n_quadrature_points; ++q)
        {
          const double w = weight(v.quadrature_point(q)) * v.JxW(q);
          if (w == 0)
            continue;
          if (!assemble)
            {
              total += w;
              continue;
            }
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c     = fe.system_to_component_index(i).first;
              double             value = c < dim ? integrand->displacement_weights[c] * v.shape_value(i, q) : 0;
              if (c < dim && integrand->rigid_fit)
                {
                  const auto row = rigid_motion_row(v.quadrature_point(q), c);
                  for (unsigned int m = 0; m < 6; ++m)
                    value += integrand->g[m] * row[m] * v.shape_value(i, q);
                }
              if (c < dim && integrand->stress_weights.norm() > 0)
                {
                  Tensor<2, dim> grad;
                  grad[c]              = v.shape_grad(i, q);
                  double     sigma_zz  = 0;
                  const auto sigma     = problem.cauchy_stress(grad, material, 0, sigma_zz);
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      value += integrand->stress_weights[a][b] * sigma[a][b];
                  value += dim == 2 ? integrand->stress_weights[2][2] * sigma_zz : 0;
                }
              cell_j[i] += w * value / total;
            }
        }
    };
    const auto visit = [&](const bool assemble) {
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && (on_boundary || cell->center().distance(centre) <= radius + cell->diameter()))
          {
            cell_j                   = 0;
            const Material &material = problem.materials.at(cell->material_id());
            if (on_boundary)
              for (const auto f : cell->face_indices())
                {
                  if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == integrand->boundary_id)
                    {
                      fe_face_values.reinit(cell, f);
                      add_points(fe_face_values, material, assemble);
                    }
                }
            else
              {
                fe_values.reinit(cell);
                add_points(fe_values, material, assemble);
              }
            if (assemble)
              {
                cell->get_dof_indices(dof_indices);
                homogeneous.distribute_local_to_global(cell_j, dof_indices, j);
              }
          }
    };
    visit(false);
    total = Utilities::MPI::sum(total, problem.communicator);
    if (integrand->rigid_fit && total > 0)
      total = 1; // an integral, not a mean
    if (!(total > 0))
      return false; // no quadrature point under the bump: the caller falls back
    j.reinit(problem.locally_owned_dofs, problem.communicator);
    visit(true);
    j.compress(VectorOperation::add);
    return true;
  }

  template bool assemble_goal_functional<2>(const LinearElasticProblem<2> &, const std::string &, const Quantities &,
                                            const AffineConstraints<double> &, PETScWrappers::MPI::Vector &,
                                            PETScWrappers::MPI::Vector &, double);
  template bool assemble_goal_functional<3>(const LinearElasticProblem<3> &, const std::string &, const Quantities &,
                                            const AffineConstraints<double> &, PETScWrappers::MPI::Vector &,
                                            PETScWrappers::MPI::Vector &, double);
} // namespace compliant
