// The residual lambda f_ext - f_int of the finite-strain problem and its tangent: per cell the
// volume terms (stress, body force, the mixed pressure equation) and the boundary terms (dead
// tractions, follower pressure), then the loads and geometric stiffness of the rigid boundaries.
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include "input/expression.h"

#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    template <int dim>
    using ExpressionFields = std::map<int, std::unique_ptr<FunctionParser<dim>>>; // per boundary id

    // One assemble() pass as its cells see it: the state and switches of the pass, and the
    // scratch every cell reuses (allocated once, outside the cell loop). Response is the
    // problem's material_response, handed in as a callable because it is private to the problem.
    template <int dim, typename Response>
    class CellAssembler
    {
    public:
      CellAssembler(const Mapping<dim> &mapping, const FiniteElement<dim> &fe,
                    const Quadrature<dim> &quadrature, const Quadrature<dim - 1> &face_quadrature,
                    const PETScWrappers::MPI::Vector &u, double lambda, double thickness, bool mixed,
                    bool plane_stress, bool with_matrix, const Response &response_of);

      // Resets cell_matrix and cell_rhs to the cell's internal and body forces (and the mixed
      // pressure equation). An inverted element (det F <= 0, or no plane-stress state) counts
      // in `inverted` and ends the cell's quadrature loop: the step is cut back anyway.
      void add_volume_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                            const HyperelasticLaw &law, const Tensor<1, dim> &body_force,
                            unsigned int &inverted);
      // Adds the loads on the cell's boundary faces: dead tractions (constant and expressions)
      // and the follower pressure with its (unsymmetric) tangent.
      void add_boundary_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                              const HyperelasticLaw                                &law,
                              const std::map<int, Tensor<1, dim>>                  &dead_tractions,
                              const ExpressionFields<dim>                          &traction_fields,
                              const ExpressionFields<dim>                          &pressure_fields,
                              unsigned int                                         &inverted);

      FullMatrix<double>                   cell_matrix;
      Vector<double>                       cell_rhs;
      std::vector<types::global_dof_index> dofs;

    private:
      const PETScWrappers::MPI::Vector &u;
      const double                      lambda, thickness;
      const bool                        mixed, plane_stress, with_matrix;
      const Response                    response_of;

      const FEValuesExtractors::Vector     displacement;
      const FEValuesExtractors::Scalar     pressure;
      FEValues<dim>                        fe_values;
      FEFaceValues<dim>                    fe_face_values;
      const unsigned int                   n, n_q_points, n_face_q_points;
      std::vector<Tensor<2, dim>>          grad_u, face_grad_u;
      std::vector<double>                  p_values;
      // A displacement shape function has one nonzero component: its gradient is e_c (x) grad N,
      // and the geometric stiffness grad phi_i S : grad phi_j is (S grad N_i) . grad N_j when
      // both have the same component c, else zero.
      std::vector<Tensor<1, dim>>          grad_N, S_grad_N;
      std::vector<unsigned int>            component;
      // The same per-i data laid out by entry for the displacement-only pair loop: dE with its
      // off-diagonal entries doubled (so that dE_i : C dE_j is one dot product of the stored
      // entries), C dE, and grad N_j under each component c (zero where j's component is not c).
      static constexpr unsigned int        n_sym = dim * (dim + 1) / 2;
      std::vector<double>                  dE_entries, C_dE_entries, grad_N_by_component;
      std::vector<SymmetricTensor<2, dim>> dE, C_dE;
      std::vector<double>                  q_phi;
      std::vector<bool>                    is_u;
      Vector<double>                       field_value, pressure_value;

      // Row i of the displacement-only tangent, j <= i: dE_i : C dE_j + (S grad N_i) . grad N_j
      // (same component), times JxW; a loop over j on contiguous entries. SimdArray comes from
      // fast_solver/simd.h, which the build puts first into every translation unit.
      void add_displacement_row(const unsigned int i, const double JxW)
      {
        Assert(!mixed && component[i] < dim, ExcInternalError());
        double a[n_sym], g[dim];
        for (unsigned int m = 0; m < n_sym; ++m)
          a[m] = dE_entries[m * n + i] * JxW;
        for (unsigned int d = 0; d < dim; ++d)
          g[d] = S_grad_N[i][d] * JxW;
        const double *C_dE_data = C_dE_entries.data();
        const double *grad_N_c  = grad_N_by_component.data() + component[i] * dim * n;
        double       *row       = &cell_matrix(i, 0);
        // On SIMD lanes (fast_solver/simd.h) while a whole chunk of j fits, then one by one.
        using Lanes                  = fast_solver::SimdArray<double>;
        constexpr unsigned int lanes = Lanes::size();
        unsigned int           j     = 0;
        for (; j + lanes <= i + 1; j += lanes)
          {
            Lanes k = 0., entry;
            for (unsigned int m = 0; m < n_sym; ++m)
              {
                entry.load(C_dE_data + m * n + j);
                k += a[m] * entry;
              }
            for (unsigned int d = 0; d < dim; ++d)
              {
                entry.load(grad_N_c + d * n + j);
                k += g[d] * entry;
              }
            entry.load(row + j);
            entry += k;
            entry.store(row + j);
          }
        for (; j <= i; ++j)
          {
            double k = 0;
            for (unsigned int m = 0; m < n_sym; ++m)
              k += a[m] * C_dE_data[m * n + j];
            for (unsigned int d = 0; d < dim; ++d)
              k += g[d] * grad_N_c[d * n + j];
            row[j] += k;
          }
      }
    };

    template <int dim, typename Response>
    CellAssembler<dim, Response>::CellAssembler(const Mapping<dim>               &mapping,
                                                const FiniteElement<dim>         &fe,
                                                const Quadrature<dim>            &quadrature,
                                                const Quadrature<dim - 1>        &face_quadrature,
                                                const PETScWrappers::MPI::Vector &u,
                                                const double                      lambda,
                                                const double                      thickness,
                                                const bool                        mixed,
                                                const bool                        plane_stress,
                                                const bool                        with_matrix,
                                                const Response                   &response_of)
      : cell_matrix(fe.n_dofs_per_cell(), fe.n_dofs_per_cell())
      , cell_rhs(fe.n_dofs_per_cell())
      , dofs(fe.n_dofs_per_cell())
      , u(u)
      , lambda(lambda)
      , thickness(thickness)
      , mixed(mixed)
      , plane_stress(plane_stress)
      , with_matrix(with_matrix)
      , response_of(response_of)
      , displacement(0)
      , pressure(dim)
      , fe_values(mapping, fe, quadrature, update_values | update_gradients | update_JxW_values)
      , fe_face_values(mapping, fe, face_quadrature,
                       update_values | update_gradients | update_JxW_values | update_quadrature_points |
                         update_normal_vectors)
      , n(fe.n_dofs_per_cell())
      , n_q_points(quadrature.size())
      , n_face_q_points(face_quadrature.size())
      , grad_u(n_q_points)
      , face_grad_u(n_face_q_points)
      , p_values(n_q_points)
      , grad_N(n)
      , S_grad_N(n)
      , component(n)
      , dE_entries(n_sym * n)
      , C_dE_entries(n_sym * n)
      , grad_N_by_component(dim * dim * n)
      , dE(n)
      , C_dE(n)
      , q_phi(n)
      , is_u(n)
      , field_value(dim)
      , pressure_value(1)
    {
      for (unsigned int i = 0; i < n; ++i)
        {
          component[i] = fe.system_to_component_index(i).first;
          is_u[i]      = component[i] < dim;
        }
    }

    template <int dim, typename Response>
    void CellAssembler<dim, Response>::add_volume_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const HyperelasticLaw                                &law,
      const Tensor<1, dim>                                 &body_force,
      unsigned int                                         &inverted)
    {
      fe_values.reinit(cell);
      fe_values[displacement].get_function_gradients(u, grad_u);
      if (mixed)
        fe_values[pressure].get_function_values(u, p_values);
      cell_matrix = 0;
      cell_rhs    = 0;
      for (unsigned int q = 0; q < n_q_points; ++q)
        {
          const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u[q];
          if (!(determinant(F) > 0))
            {
              ++inverted;
              break;
            }
          const auto   E        = green_lagrange(grad_u[q]);
          const auto   response = response_of(law, E, mixed ? p_values[q] : 0.0, with_matrix);
          if (!std::isfinite(response.S.norm()))
            {
              ++inverted; // no plane-stress state: as bad as an inverted element
              break;
            }
          const double JxW      = fe_values.JxW(q) * thickness;
          const Tensor<2, dim> S    = response.S;
          // A displacement shape function e_c N has gradient e_c (x) grad N: its virtual strain
          // is sym(F^T e_c (x) grad N) = sym(F[c] (x) grad N), and S : dE = (F S)[c] . grad N
          // (the first Piola stress), so the residual needs no tensor per shape function.
          const Tensor<2, dim> P    = F * S;
          for (unsigned int i = 0; i < n; ++i)
            {
              if (is_u[i])
                {
                  const unsigned int c = component[i];
                  grad_N[i]            = fe_values.shape_grad(i, q);
                  cell_rhs(i) -= (P[c] * grad_N[i] - body_force[c] * fe_values.shape_value(i, q)) * JxW;
                  if (!with_matrix) // a residual alone needs no more
                    continue;
                  for (unsigned int k = 0; k < dim; ++k)
                    for (unsigned int l = k; l < dim; ++l)
                      dE[i][k][l] = 0.5 * (F[c][k] * grad_N[i][l] + F[c][l] * grad_N[i][k]);
                  C_dE[i]     = response.tangent * dE[i];
                  S_grad_N[i] = S * grad_N[i]; // geometric stiffness, once per i
                  if (mixed)
                    continue;
                  for (unsigned int m = 0; m < n_sym; ++m)
                    {
                      dE_entries[m * n + i]   = (m < dim ? 1. : 2.) * dE[i].access_raw_entry(m);
                      C_dE_entries[m * n + i] = C_dE[i].access_raw_entry(m);
                    }
                  for (unsigned int d = 0; d < dim; ++d)
                    grad_N_by_component[(c * dim + d) * n + i] = grad_N[i][d];
                }
              else
                {
                  q_phi[i] = fe_values.shape_value(i, q);
                  cell_rhs(i) -= (response.log_J - p_values[q] / law.lambda()) * q_phi[i] * JxW;
                }
            }
          if (!with_matrix)
            continue;
          const auto Ci = mixed ? invert(unit_symmetric_tensor<dim>() + 2 * E) : SymmetricTensor<2, dim>();
          for (unsigned int i = 0; i < n; ++i)
            {
              // The volume tangent is symmetric: the lower triangle, mirrored after the
              // quadrature loop (the follower-pressure part is not symmetric).
              if (!mixed)
                {
                  add_displacement_row(i, JxW);
                  continue;
                }
              for (unsigned int j = 0; j <= i; ++j)
                {
                  double k = 0;
                  if (is_u[i] && is_u[j])
                    k = dE[i] * C_dE[j] + (component[i] == component[j] ? S_grad_N[i] * grad_N[j] : 0.);
                  else if (is_u[i])
                    k = (dE[i] * Ci) * q_phi[j];
                  else if (is_u[j])
                    k = (dE[j] * Ci) * q_phi[i];
                  else
                    k = -q_phi[i] * q_phi[j] / law.lambda();
                  cell_matrix(i, j) += k * JxW;
                }
            }
        }
      if (with_matrix)
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < i; ++j)
            cell_matrix(j, i) = cell_matrix(i, j);
    }

    template <int dim, typename Response>
    void CellAssembler<dim, Response>::add_boundary_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const HyperelasticLaw                                &law,
      const std::map<int, Tensor<1, dim>>                  &dead_tractions,
      const ExpressionFields<dim>                          &traction_fields,
      const ExpressionFields<dim>                          &pressure_fields,
      unsigned int                                         &inverted)
    {
      for (const auto f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary())
            continue;
          const int  id        = cell->face(f)->boundary_id();
          const auto dead      = dead_tractions.find(id);
          const auto field     = traction_fields.find(id);
          const auto follower  = pressure_fields.find(id);
          if (dead == dead_tractions.end() && field == traction_fields.end() &&
              follower == pressure_fields.end())
            continue;
          fe_face_values.reinit(cell, f);
          if (follower != pressure_fields.end())
            fe_face_values[displacement].get_function_gradients(u, face_grad_u);
          for (unsigned int q = 0; q < n_face_q_points; ++q)
            {
              const double dA = fe_face_values.JxW(q) * thickness;
              Tensor<1, dim> t;
              if (dead != dead_tractions.end())
                t += dead->second;
              if (field != traction_fields.end())
                {
                  field->second->vector_value(fe_face_values.quadrature_point(q), field_value);
                  for (unsigned int d = 0; d < dim; ++d)
                    t[d] += field_value[d];
                }
              t *= lambda;
              // Follower pressure on the deformed surface: t dA = -p cof(F) N dA0. In plane
              // stress the loaded area also follows the thickness stretch lambda_3 =
              // sqrt(1 + 2 E33), E33 from S33 = 0 at this point: t dA = -p lambda_3 cof(F) N dA0.
              Tensor<2, dim>          F, F_inv_T, cof;
              SymmetricTensor<2, dim> dlambda3_dE;
              double                  p = 0, lambda3 = 1;
              const auto              N = fe_face_values.normal_vector(q);
              if (follower != pressure_fields.end())
                {
                  follower->second->vector_value(fe_face_values.quadrature_point(q), pressure_value);
                  p       = lambda * pressure_value[0];
                  F       = unit_symmetric_tensor<dim>() + face_grad_u[q];
                  F_inv_T = transpose(invert(F));
                  cof     = determinant(F) * F_inv_T;
                  if (plane_stress)
                    {
                      const auto response = response_of(
                        law, 0.5 * (symmetrize(transpose(F) * F) - unit_symmetric_tensor<dim>()), 0.0, true);
                      if (!std::isfinite(response.E33) || !(1 + 2 * response.E33 > 0))
                        {
                          ++inverted; // no plane-stress state here: cut the step back
                          continue;
                        }
                      lambda3     = std::sqrt(1 + 2 * response.E33);
                      dlambda3_dE = response.dE33_dE / lambda3;
                    }
                  t -= p * lambda3 * (cof * N);
                }
              for (unsigned int i = 0; i < n; ++i)
                {
                  if (!is_u[i])
                    continue;
                  const auto phi_i = fe_face_values[displacement].value(i, q);
                  cell_rhs(i) += phi_i * t * dA;
                  if (!with_matrix || follower == pressure_fields.end())
                    continue;
                  for (unsigned int j = 0; j < n; ++j)
                    {
                      if (!is_u[j])
                        continue;
                      // d cof(F)[dF] = J (F^-T : dF) F^-T - J F^-T dF^T F^-T
                      const auto dF   = fe_face_values[displacement].gradient(j, q);
                      const auto dcof = determinant(F) * (scalar_product(F_inv_T, dF) * F_inv_T -
                                                          F_inv_T * transpose(dF) * F_inv_T);
                      double dlambda3 = 0;
                      if (plane_stress)
                        dlambda3 = dlambda3_dE * symmetrize(transpose(F) * dF);
                      cell_matrix(i, j) += p * (phi_i * (lambda3 * (dcof * N) + dlambda3 * (cof * N))) * dA;
                    }
                }
            }
        }
    }
  } // namespace

  template <int dim>
  void FiniteStrainProblem<dim>::assemble(const PETScWrappers::MPI::Vector &u, const double lambda,
                                          const AffineConstraints<double> *constraints,
                                          const bool                       with_matrix,
                                          PETScWrappers::MPI::Vector      &residual,
                                          PETScWrappers::MPI::Vector      *full_residual) const
  {
    if (with_matrix && constraints != nullptr)
      cover_contact_couplings(*constraints);
    if (with_matrix)
      tangent = 0;
    residual = 0;
    if (full_residual != nullptr)
      *full_residual = 0;
    const auto response_of = [this](const HyperelasticLaw &law, const SymmetricTensor<2, dim> &E,
                                    const double pressure, const bool with_tangent) {
      return material_response(law, E, pressure, with_tangent);
    };
    CellAssembler<dim, decltype(response_of)> cells(*mapping, *fe, *quadrature, *face_quadrature, u, lambda,
                                                    thickness, mixed, plane_stress, with_matrix, response_of);

    ExpressionFields<dim> traction_fields, pressure_fields;
    for (const auto &[id, e] : boundary_conditions.traction_fields)
      traction_fields[id] = make_field_function<dim>(e, parameters.geometry_parameters, "Loads/Traction");
    for (const auto &[id, e] : follower_pressures)
      pressure_fields[id] = make_field_function<dim>(e, parameters.geometry_parameters, "Finite strain/Follower pressure");

    // Forces on rigid boundaries (unconstrained), for their geometric stiffness.
    const bool rigid_condensed = constraints != nullptr && constraints != &hanging_node_constraints &&
                                 constraints->get_local_lines().size() > 0;
    const bool rigid_stiffness = with_matrix && rigid_condensed && !rigid_boundaries.empty();
    PETScWrappers::MPI::Vector boundary_forces;
    if (rigid_stiffness)
      boundary_forces.reinit(locally_owned_dofs, communicator);

    unsigned int inverted = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const HyperelasticLaw &law      = laws.at(cell->material_id());
          const Material        &material = materials.at(cell->material_id());
          const auto body_force = lambda * (boundary_conditions.body_force +
                                            material.density * boundary_conditions.gravity);
          cells.add_volume_terms(cell, law, body_force, inverted);
          cells.add_boundary_terms(cell, law, dead_tractions, traction_fields, pressure_fields, inverted);

          const FullMatrix<double> &cell_matrix = cells.cell_matrix;
          const Vector<double>     &cell_rhs    = cells.cell_rhs;
          auto                     &dofs        = cells.dofs;
          cell->get_dof_indices(dofs);
          if (full_residual != nullptr)
            hanging_node_constraints.distribute_local_to_global(cell_rhs, dofs, *full_residual);
          if (rigid_stiffness)
            hanging_node_constraints.distribute_local_to_global(cell_rhs, dofs, boundary_forces);
          if (constraints != nullptr && with_matrix)
            constraints->distribute_local_to_global(cell_matrix, cell_rhs, dofs, tangent, residual);
          else if (constraints != nullptr)
            constraints->distribute_local_to_global(cell_rhs, dofs, residual);
          else
            residual.add(dofs, cell_rhs);
        }
    // Loads of rigid boundaries: condensed onto the masters where the constraints hold the rigid
    // lines (those from make_constraints, reinitialised on the relevant DoFs), else nodal.
    if (rigid_stiffness)
      {
        boundary_forces.compress(VectorOperation::add);
        for (const auto &rigid : rigid_boundaries)
          rigid.add_geometric_stiffness(boundary_forces, lambda, tangent);
      }
    for (const auto &rigid : rigid_boundaries)
      {
        rigid.add_load(lambda, rigid_condensed ? constraints : nullptr, residual);
        if (full_residual != nullptr)
          rigid.add_load(lambda, nullptr, *full_residual);
      }
    if (contact) // the friction of slipping contact nodes: an external force, and its derivative
      {
        contact->add_friction_forces(constraints, residual, full_residual);
        if (with_matrix)
          contact->add_friction_stiffness(constraints, tangent);
      }
    if (with_matrix)
      tangent.compress(VectorOperation::add);
    residual.compress(VectorOperation::add);
    if (full_residual != nullptr)
      full_residual->compress(VectorOperation::add);
    if (Utilities::MPI::sum(inverted, communicator) > 0)
      throw StepFailure("an element inverted (det F <= 0, or no plane-stress thickness) at load factor " +
                        std::to_string(lambda));
  }

#define INSTANTIATE(dim)                                                                                       \
  template void FiniteStrainProblem<dim>::assemble(const PETScWrappers::MPI::Vector &, double,                \
                                                   const AffineConstraints<double> *, bool,                  \
                                                   PETScWrappers::MPI::Vector &, PETScWrappers::MPI::Vector *) \
    const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace compliant
