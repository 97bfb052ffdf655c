#include "finite_strain/finite_strain_problem.h"

#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include "elasticity/rigid_rotation.h"
#include "fast_solver/p_multigrid_solver.h"
#include "fast_solver/tangent_operator.h"
#include "elasticity/von_mises.h"
#include "input/spec_list.h"
#include "linear_algebra/petsc_linear_solver.h"
#include "linear_algebra/rigid_body_modes.h"
#include "mesh/mesh_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // A vector function multiplied by the load factor.
    template <int dim>
    class Scaled : public Function<dim>
    {
    public:
      Scaled(const Function<dim> &f, double factor) : Function<dim>(dim), f(f), factor(factor) {}
      void vector_value(const Point<dim> &p, Vector<double> &v) const override
      {
        f.vector_value(p, v);
        v *= factor;
      }

    private:
      const Function<dim> &f;
      double               factor;
    };

    template <int dim>
    std::unique_ptr<FunctionParser<dim>> make_parser(const std::vector<std::string> &expressions,
                                                     const std::map<std::string, double> &constants,
                                                     const std::string &where)
    {
      auto parser = std::make_unique<FunctionParser<dim>>(expressions.size());
      try
        {
          parser->initialize(dim == 2 ? "x,y" : "x,y,z", expressions, constants);
          Vector<double> probe(expressions.size());
          parser->vector_value(Point<dim>(), probe);
        }
      catch (const std::exception &)
        {
          throw std::invalid_argument(where + ": cannot evaluate '" + expressions[0] +
                                      "'; use x, y, z and geometry parameters");
        }
      return parser;
    }

    template <int dim>
    SymmetricTensor<2, dim> sym(const Tensor<2, dim> &t)
    {
      return symmetrize(t);
    }

  } // namespace

  template <int dim>
  FiniteStrainProblem<dim>::FiniteStrainProblem(const CaseParameters       &parameters,
                                                const FiniteStrainSettings &settings,
                                                const MeshedGeometry       &geometry,
                                                MPI_Comm                    communicator,
                                                const MeshPartitionChoice  &partition)
    : Discretization<dim>(parameters, geometry, communicator, partition)
    , settings(settings)
  {
    mixed = settings.mixed;
  }

  template <int dim>
  FiniteStrainProblem<dim>::~FiniteStrainProblem() = default;

  template <int dim>
  StressResponse<dim> FiniteStrainProblem<dim>::material_response(const HyperelasticLaw &law,
                                                                  const SymmetricTensor<2, dim> &E,
                                                                  const double pressure) const
  {
    if constexpr (dim == 2)
      if (plane_stress)
        return law.plane_stress_response(E);
    return law.response(E, mixed, pressure);
  }

  template <int dim>
  void FiniteStrainProblem<dim>::setup()
  {
    this->check_mesh_dimension();
    if (plane_stress && mixed)
      throw std::invalid_argument("Finite strain/Formulation: plane stress is displacement-only "
                                  "(the thickness strain takes up the volume change, nothing locks)");
    this->create_mesh();
    if (!triangulation.all_reference_cells_are_hyper_cube())
      throw std::invalid_argument("Finite strain: the mesh must be quadrilaterals/hexahedra");
    this->choose_element(mixed);

    this->assign_materials();
    for (const auto &[id, material] : materials)
      laws.emplace(id, HyperelasticLaw(settings.law, material, settings.mooney_rivlin_ratio));
    if (mixed && !laws.begin()->second.supports_mixed())
      throw std::invalid_argument("Finite strain/Formulation: the mixed formulation needs the "
                                  "neo-Hookean or Mooney-Rivlin law");
    this->resolve_boundary_conditions();
    if (!boundary_conditions.total_forces.empty())
      throw std::invalid_argument("Loads/Total force: not available in finite strain (the loaded "
                                  "area changes); use Traction (dead, per reference area)");
    if (!boundary_conditions.pressures.empty())
      throw std::invalid_argument("Loads/Pressure: acts on the undeformed boundary, a linear load; at "
                                  "finite strain use Finite strain/Follower pressure (it turns and "
                                  "stretches with the surface)");
    dead_tractions = boundary_conditions.tractions;
    for (const auto &item : parse_spec_list(settings.follower_pressure, "Finite strain/Follower pressure"))
      {
        if (item.fields.size() != 1 || !item.fields[0].key.empty())
          throw std::invalid_argument("Finite strain/Follower pressure: expected 'boundary: p'");
        follower_pressures[boundary_id_of(item.name, geometry.boundary_ids,
                                          "Finite strain/Follower pressure")] = {item.fields[0].value};
      }
    for (const auto &[id, expressions] : boundary_conditions.traction_fields)
      make_parser<dim>(expressions, parameters.geometry_parameters, "Loads/Traction");
    for (const auto &[id, expressions] : follower_pressures)
      make_parser<dim>(expressions, parameters.geometry_parameters, "Finite strain/Follower pressure");

    this->distribute_dofs();
    solution.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);

    rigid_boundaries.clear();
    for (const auto &load : boundary_conditions.rigid)
      rigid_boundaries.emplace_back(load, dof_handler, *mapping, hanging_node_constraints, communicator);

    const PETScWrappers::MPI::Vector zero(locally_owned_dofs, locally_relevant_dofs, communicator);
    const auto constraints = make_constraints(0, true, zero, true); // refuses supported rigid nodes
    reinit_matrix(tangent, dof_handler, constraints, rigid_boundaries, locally_owned_dofs, locally_relevant_dofs,
                  communicator);
  }

  template <int dim>
  AffineConstraints<double>
  FiniteStrainProblem<dim>::make_constraints(const double lambda, const bool homogeneous,
                                             const PETScWrappers::MPI::Vector &u,
                                             const bool for_sparsity) const
  {
    AffineConstraints<double> constraints;
    constraints.reinit(locally_relevant_dofs);
    // Hanging nodes first (adaptive meshes from the model ladder): a hanging DoF on a supported
    // boundary follows its masters, which carry the prescribed values.
    constraints.merge(hanging_node_constraints);
    const ComponentMask displacement = fe->component_mask(FEValuesExtractors::Vector(0));
    std::vector<bool>   all(fe->n_components(), false);
    for (unsigned int d = 0; d < dim; ++d)
      all[d] = true;
    for (const auto &[name, id] : boundary_conditions.clamped)
      VectorTools::interpolate_boundary_values(*mapping, dof_handler, id,
                                               Functions::ZeroFunction<dim>(fe->n_components()),
                                               constraints, displacement);
    for (const auto &d : boundary_conditions.displacements)
      {
        auto parser = make_parser<dim>(d.expressions, parameters.geometry_parameters,
                                       "Boundary conditions/Displacement");
        std::vector<bool> mask(fe->n_components(), false);
        for (unsigned int c = 0; c < dim; ++c)
          mask[c] = d.mask[c];
        // pad the parser to all components (pressure: unused)
        class Padded : public Function<dim>
        {
        public:
          Padded(const Function<dim> &f, double s, unsigned int n) : Function<dim>(n), f(f), s(s) {}
          void vector_value(const Point<dim> &p, Vector<double> &v) const override
          {
            Vector<double> w(dim);
            f.vector_value(p, w);
            v = 0;
            for (unsigned int c = 0; c < dim; ++c)
              v[c] = s * w[c];
          }
          const Function<dim> &f;
          double               s;
        };
        VectorTools::interpolate_boundary_values(*mapping, dof_handler, d.boundary_id,
                                                 Padded(*parser, lambda, fe->n_components()),
                                                 constraints, ComponentMask(mask));
      }
    for (const auto &r : boundary_conditions.rotations)
      {
        class PaddedRotation : public Function<dim>
        {
        public:
          PaddedRotation(const RigidRotation<dim> &f, unsigned int n) : Function<dim>(n), f(f) {}
          void vector_value(const Point<dim> &p, Vector<double> &v) const override
          {
            Vector<double> w(dim);
            f.vector_value(p, w);
            v = 0;
            for (unsigned int c = 0; c < dim; ++c)
              v[c] = w[c];
          }
          const RigidRotation<dim> &f;
        };
        const RigidRotation<dim> rotation(lambda * r.angle, r.center, r.axis);
        VectorTools::interpolate_boundary_values(*mapping, dof_handler, r.boundary_id,
                                                 PaddedRotation(rotation, fe->n_components()),
                                                 constraints, displacement);
      }
    for (auto &rigid : rigid_boundaries)
      {
        if (!for_sparsity)
          rigid.linearize(&u);
        rigid.add_constraints(constraints, for_sparsity);
      }
    // Newton solves for the correction: the Dirichlet value minus the current displacement.
    // (Hanging-node lines stay homogeneous: the displacement satisfies them at every step.)
    for (const auto &line : constraints.get_lines())
      if (line.entries.empty())
        constraints.set_inhomogeneity(line.index, homogeneous ? 0. : line.inhomogeneity - u[line.index]);
    constraints.close();
    return constraints;
  }

  template <int dim>
  void FiniteStrainProblem<dim>::assemble(const PETScWrappers::MPI::Vector &u, const double lambda,
                                          const AffineConstraints<double> *constraints,
                                          const bool                       with_matrix,
                                          PETScWrappers::MPI::Vector      &residual,
                                          PETScWrappers::MPI::Vector      *full_residual) const
  {
    if (with_matrix)
      tangent = 0;
    residual = 0;
    if (full_residual != nullptr)
      *full_residual = 0;
    const FEValuesExtractors::Vector displacement(0);
    const FEValuesExtractors::Scalar pressure(dim);
    FEValues<dim>     fe_values(*mapping, *fe, *quadrature,
                            update_values | update_gradients | update_JxW_values);
    FEFaceValues<dim> fe_face_values(*mapping, *fe, *face_quadrature,
                                     update_values | update_gradients | update_JxW_values |
                                       update_quadrature_points | update_normal_vectors);
    const unsigned int n = fe->n_dofs_per_cell();
    FullMatrix<double> cell_matrix(n, n);
    Vector<double>     cell_rhs(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Tensor<2, dim>>          grad_u(quadrature->size()), face_grad_u(face_quadrature->size());
    std::vector<double>                  p_values(quadrature->size());
    std::vector<Tensor<2, dim>>          grad_phi(n), grad_phi_S(n);
    std::vector<SymmetricTensor<2, dim>> dE(n), C_dE(n);
    std::vector<Tensor<1, dim>>          phi(n);
    std::vector<double>                  q_phi(n);
    std::vector<bool>                    is_u(n);
    for (unsigned int i = 0; i < n; ++i)
      is_u[i] = fe->system_to_component_index(i).first < dim;

    std::map<int, std::unique_ptr<FunctionParser<dim>>> traction_fields, pressure_fields;
    for (const auto &[id, e] : boundary_conditions.traction_fields)
      traction_fields[id] = make_parser<dim>(e, parameters.geometry_parameters, "Loads/Traction");
    for (const auto &[id, e] : follower_pressures)
      pressure_fields[id] = make_parser<dim>(e, parameters.geometry_parameters, "Follower pressure");
    Vector<double> field_value(dim), pressure_value(1);

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
          fe_values.reinit(cell);
          fe_values[displacement].get_function_gradients(u, grad_u);
          if (mixed)
            fe_values[pressure].get_function_values(u, p_values);
          cell_matrix = 0;
          cell_rhs    = 0;
          const HyperelasticLaw &law        = laws.at(cell->material_id());
          const Material        &material   = materials.at(cell->material_id());
          const auto body_force = lambda * (boundary_conditions.body_force +
                                            material.density * boundary_conditions.gravity);
          for (unsigned int q = 0; q < quadrature->size(); ++q)
            {
              const Tensor<2, dim> F = unit_symmetric_tensor<dim>() + grad_u[q];
              if (!(determinant(F) > 0))
                {
                  ++inverted;
                  break;
                }
              const auto   E        = green_lagrange(grad_u[q]);
              const auto   response = material_response(law, E, mixed ? p_values[q] : 0.0);
              if (!std::isfinite(response.S.norm()))
                {
                  ++inverted; // no plane-stress state: as bad as an inverted element
                  break;
                }
              const double JxW      = fe_values.JxW(q) * thickness;
              const auto   Ci       = invert(unit_symmetric_tensor<dim>() + 2 * E);
              const Tensor<2, dim> S    = response.S;
              for (unsigned int i = 0; i < n; ++i)
                {
                  if (is_u[i])
                    {
                      grad_phi[i] = fe_values[displacement].gradient(i, q);
                      phi[i]      = fe_values[displacement].value(i, q);
                      dE[i]       = sym(transpose(F) * grad_phi[i]);
                      C_dE[i]     = response.tangent * dE[i];
                      grad_phi_S[i] = grad_phi[i] * S; // geometric stiffness, once per i
                    }
                  else
                    q_phi[i] = fe_values[pressure].value(i, q);
                }
              for (unsigned int i = 0; i < n; ++i)
                {
                  if (is_u[i])
                    cell_rhs(i) -= (response.S * dE[i] - body_force * phi[i]) * JxW;
                  else
                    cell_rhs(i) -= (response.log_J - p_values[q] / law.lambda()) * q_phi[i] * JxW;
                  if (!with_matrix)
                    continue;
                  // The volume tangent is symmetric: the lower triangle, mirrored after the
                  // quadrature loop (the follower-pressure part below is not symmetric).
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      double k = 0;
                      if (is_u[i] && is_u[j])
                        k = dE[i] * C_dE[j] + scalar_product(grad_phi_S[i], grad_phi[j]);
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
              for (unsigned int q = 0; q < face_quadrature->size(); ++q)
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
                          const auto response = material_response(
                            law, 0.5 * (symmetrize(transpose(F) * F) - unit_symmetric_tensor<dim>()), 0.0);
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
    if (with_matrix)
      tangent.compress(VectorOperation::add);
    residual.compress(VectorOperation::add);
    if (full_residual != nullptr)
      full_residual->compress(VectorOperation::add);
    if (Utilities::MPI::sum(inverted, communicator) > 0)
      throw StepFailure("an element inverted (det F <= 0, or no plane-stress thickness) at load factor " +
                        std::to_string(lambda));
  }

  template <int dim>
  double FiniteStrainProblem<dim>::residual_norm(const PETScWrappers::MPI::Vector &u,
                                                 const double                      lambda,
                                                 const AffineConstraints<double>  &homogeneous) const
  {
    PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
    ghosted = u;
    PETScWrappers::MPI::Vector rhs(locally_owned_dofs, communicator);
    assemble(ghosted, lambda, &homogeneous, false, rhs);
    return rhs.l2_norm();
  }

  template <int dim>
  void FiniteStrainProblem<dim>::add_correction(PETScWrappers::MPI::Vector &u, const double alpha,
                                                const PETScWrappers::MPI::Vector &du) const
  {
    u.add(alpha, du);
    if (rigid_boundaries.empty())
      return;
    for (const auto &rigid : rigid_boundaries)
      rigid.move(du, alpha, u);
    // Hanging nodes on a rigid boundary follow its exact motion too.
    hanging_node_constraints.distribute(u);
  }

  template <int dim>
  SymmetricTensor<2, dim> FiniteStrainProblem<dim>::cauchy_stress(const Tensor<2, dim> &grad_u,
                                                                  const Material &material,
                                                                  const double    pressure,
                                                                  double         &sigma_zz) const
  {
    const HyperelasticLaw law(settings.law, material, settings.mooney_rivlin_ratio);
    const Tensor<2, dim>  F = unit_symmetric_tensor<dim>() + grad_u;
    const auto            r = material_response(law, green_lagrange(grad_u), pressure);
    // in plane stress J includes the thickness stretch sqrt(C33)
    const double J = determinant(F) * (plane_stress ? std::sqrt(1 + 2 * r.E33) : 1.0);
    sigma_zz       = r.S33 / J;
    return sym(F * Tensor<2, dim>(r.S) * transpose(F)) / J;
  }

  template <int dim>
  double FiniteStrainProblem<dim>::von_mises(const SymmetricTensor<2, dim> &s, const double sigma_zz) const
  {
    return von_mises_stress(s, sigma_zz);
  }

  template <int dim>
  double FiniteStrainProblem<dim>::energy_density(const Tensor<2, dim> &grad_u,
                                                  const Material       &material, double) const
  {
    const HyperelasticLaw law(settings.law, material, settings.mooney_rivlin_ratio);
    return material_response(law, green_lagrange(grad_u), 0.0).energy;
  }

  template <int dim>
  PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::reaction_forces() const
  {
    PETScWrappers::MPI::Vector residual(locally_owned_dofs, communicator);
    // Condensed over hanging nodes (C^T r): reactions on adaptive meshes sum over the masters.
    assemble(solution, load_factor, &hanging_node_constraints, false, residual);
    residual *= -1; // assemble gives f_ext - f_int
    return residual;
  }

  template <int dim>
  std::map<std::string, double> FiniteStrainProblem<dim>::expression_variables() const
  {
    auto variables           = Base::expression_variables();
    variables["load_factor"] = load_factor;
    return variables;
  }

  template class FiniteStrainProblem<2>;
  template class FiniteStrainProblem<3>;
} // namespace compliant
