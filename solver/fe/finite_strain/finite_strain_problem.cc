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
#include "input/expression.h"
#include "input/spec_list.h"
#include "linear_algebra/petsc_linear_solver.h"
#include "constraints/rigid_motion_check.h"
#include "linear_algebra/rigid_body_modes.h"
#include "mesh/mesh_reader.h"

#include <algorithm>
#include <limits>
#include <set>
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
                                                                  const double pressure,
                                                                  const bool   with_tangent) const
  {
    if constexpr (dim == 2)
      if (plane_stress)
        return law.plane_stress_response(E);
    return law.response(E, mixed, pressure, with_tangent);
  }

  template <int dim>
  void FiniteStrainProblem<dim>::setup()
  {
    this->check_mesh_dimension();
    if (plane_stress && mixed)
      throw std::invalid_argument("Finite strain/Formulation: plane stress is displacement-only "
                                  "(the thickness strain takes up the volume change, nothing locks)");
    if (parameters.reduced_integration && mixed)
      throw std::invalid_argument("Discretization/Integration = reduced: for the displacement formulation, not "
                                  "Finite strain/Formulation = mixed (its pressure space needs the full rule)");
    this->create_mesh();
    if (!triangulation.all_reference_cells_are_hyper_cube())
      throw std::invalid_argument("Finite strain: the mesh must be quadrilaterals/hexahedra");
    this->choose_element(mixed);

    this->assign_materials();
    for (const auto &[id, material] : materials)
      laws.emplace(id, HyperelasticLaw(settings.law, material, settings.mooney_rivlin_ratio, settings.law_constants));
    if (mixed && !laws.begin()->second.supports_mixed())
      throw std::invalid_argument("Finite strain/Formulation: the mixed formulation needs the "
                                  "neo-Hookean, Mooney-Rivlin, Ogden or Yeoh law");
    // Its pressure equation ln J = p / lambda divides by lambda, and the stability check's inertia
    // count takes the pressure block -M / lambda as negative definite.
    for (const auto &[id, law] : laws)
      if (mixed && !(law.lambda() > 0))
        throw std::invalid_argument("Finite strain/Formulation = mixed: material '" + materials.at(id).name +
                                    "' has a volumetric constant lambda (from nu, the bulk modulus or the "
                                    "Mooney-Rivlin c2) of " + std::to_string(law.lambda()) +
                                    " (nu = 0 gives 0); the pressure equation needs lambda > 0: use the "
                                    "displacement formulation, which does not lock without a volumetric stiffness");
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
      make_field_function<dim>(expressions, parameters.geometry_parameters, "Loads/Traction");
    for (const auto &[id, expressions] : follower_pressures)
      make_field_function<dim>(expressions, parameters.geometry_parameters, "Finite strain/Follower pressure");

    this->distribute_dofs();
    solution.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);

    rigid_boundaries.clear();
    for (const auto &load : boundary_conditions.rigid)
      rigid_boundaries.emplace_back(load, dof_handler, *mapping, hanging_node_constraints, communicator);

    set_up_extra_constraints();
    set_up_contact();
    const PETScWrappers::MPI::Vector zero(locally_owned_dofs, locally_relevant_dofs, communicator);
    const auto constraints = make_constraints(0, true, zero, true); // refuses supported rigid nodes
    reinit_matrix(tangent, dof_handler, constraints, rigid_boundaries, locally_owned_dofs, locally_relevant_dofs,
                  communicator);
  }

  template <int dim>
  void FiniteStrainProblem<dim>::require_rigid_motion_held(const std::string &what) const
  {
    const PETScWrappers::MPI::Vector zero(locally_owned_dofs, locally_relevant_dofs, communicator);
    compliant::require_rigid_motion_held(*mapping, dof_handler, make_constraints(0, true, zero), rigid_boundaries,
                                         what);
  }

  template <int dim>
  double FiniteStrainProblem<dim>::correction_round_off() const
  {
    if (rigid_boundaries.empty())
      return 0;
    if (largest_coordinate < 0)
      {
        double largest = 0;
        for (const auto &vertex : triangulation.get_vertices())
          largest = std::max(largest, vertex.norm());
        largest_coordinate = Utilities::MPI::max(largest, communicator); // one verdict on every rank
      }
    return 8 * std::numeric_limits<double>::epsilon() * largest_coordinate * std::sqrt(double(dof_handler.n_dofs()));
  }

  template <int dim>
  const PETScWrappers::MPI::Vector &FiniteStrainProblem<dim>::pressure_weights() const
  {
    if (pressure_weight.size() == dof_handler.n_dofs())
      return pressure_weight;
    double mu = 0, volume = 0;
    for (const auto &[id, law] : laws)
      mu = std::max(mu, law.small_strain_shear_modulus());
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        volume += cell->measure();
    volume                     = Utilities::MPI::sum(volume, communicator);
    const double h             = std::pow(volume / triangulation.n_global_active_cells(), 1. / dim);
    const double weight        = mu > 0 && h > 0 ? mu / h : 1.;
    ComponentMask pressure_only(dim + 1, false);
    pressure_only.set(dim, true);
    const IndexSet pressures = DoFTools::extract_dofs(dof_handler, pressure_only);
    pressure_weight.reinit(locally_owned_dofs, communicator);
    inverse_pressure_weight.reinit(locally_owned_dofs, communicator);
    for (const auto index : locally_owned_dofs)
      {
        pressure_weight(index)         = pressures.is_element(index) ? weight : 1.;
        inverse_pressure_weight(index) = pressures.is_element(index) ? 1. / weight : 1.;
      }
    pressure_weight.compress(VectorOperation::insert);
    inverse_pressure_weight.compress(VectorOperation::insert);
    return pressure_weight;
  }

  template <int dim>
  double FiniteStrainProblem<dim>::residual_norm_of(const PETScWrappers::MPI::Vector &residual) const
  {
    if (!mixed)
      return residual.l2_norm();
    PETScWrappers::MPI::Vector weighted(residual);
    weighted.scale(pressure_weights());
    return weighted.l2_norm();
  }

  template <int dim>
  double FiniteStrainProblem<dim>::unknown_dot(const PETScWrappers::MPI::Vector &a,
                                               const PETScWrappers::MPI::Vector &b) const
  {
    if (!mixed)
      return a * b;
    // Pressures times h / mu in both factors.
    pressure_weights();
    PETScWrappers::MPI::Vector wa(a), wb(b);
    wa.scale(inverse_pressure_weight);
    wb.scale(inverse_pressure_weight);
    return wa * wb;
  }

  template <int dim>
  AffineConstraints<double>
  FiniteStrainProblem<dim>::make_constraints(const double lambda, const bool homogeneous,
                                             const PETScWrappers::MPI::Vector &u,
                                             const bool for_sparsity) const
  {
    AffineConstraints<double> constraints;
    const bool                whole = !settings.extra.empty(); // every line on every rank
    constraints.reinit(whole ? complete_index_set(dof_handler.n_dofs()) : locally_relevant_dofs);
    // Hanging nodes first (adaptive meshes from the model ladder): a hanging DoF on a supported
    // boundary follows its masters, which carry the prescribed values.
    constraints.merge(hanging_node_constraints, AffineConstraints<double>::no_conflicts_allowed, whole);
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
        auto parser = make_field_function<dim>(d.expressions, parameters.geometry_parameters,
                                               "Boundary conditions/Displacement of '" + d.boundary + "'");
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
    // (Hanging-node lines stay homogeneous: the displacement satisfies them at every step.) With
    // every line on every rank, a DoF no line of this rank reaches keeps no correction.
    PETScWrappers::MPI::Vector extended;
    if (whole && !homogeneous)
      state_for_constraints(u, extended);
    const PETScWrappers::MPI::Vector &state = whole && !homogeneous ? extended : u;
    const auto known = [&](const types::global_dof_index i) {
      return !whole || locally_relevant_dofs.is_element(i) || extra_dofs.is_element(i);
    };
    for (const auto &line : constraints.get_lines())
      if (line.entries.empty())
        constraints.set_inhomogeneity(line.index, homogeneous || !known(line.index) ?
                                                    0. :
                                                    line.inhomogeneity - state[line.index]);
    if (whole)
      add_extra_lines(constraints);
    // Contact lines are on the correction already (n . du = -gap), after the supports they defer to.
    if (contact)
      contact->add_constraints(constraints, u, lambda, homogeneous || for_sparsity);
    constraints.close();
    return constraints;
  }

  template <int dim>
  void FiniteStrainProblem<dim>::start_contact_step()
  {
    if (!contact)
      return;
    if (contact->pairs)
      contact->pairs->save();
    if (contact->has_friction())
      {
        PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
        ghosted = solution;
        contact->start_step(ghosted, load_factor);
      }
    contact->save();
  }

  template <int dim>
  typename ContactSet<dim>::Update FiniteStrainProblem<dim>::update_contact_set(const PETScWrappers::MPI::Vector &u,
                                                                               const double lambda, const bool release,
                                                                               PETScWrappers::MPI::Vector &full)
  {
    Timer contact_timer;
    assemble(u, lambda, &hanging_node_constraints, false, full);
    const double force_tolerance = settings.residual_tolerance * residual_norm_of(full);
    const auto   update          = contact->update_active_set(u, full, lambda, release, force_tolerance);
    if (std::getenv("COMPLIANT_DEBUG_NEWTON") && Utilities::MPI::this_mpi_process(communicator) == 0)
      std::cout << "    contact: " << update.changes << " changes, " << update.pulling << " pulling, violation "
                << update.violation << std::endl;
    contact_seconds += contact_timer.wall_time();
    return update;
  }

  template <int dim>
  void FiniteStrainProblem<dim>::restore_contact_state()
  {
    // A failed Newton leaves the nodes it held or freed: back to the converged state's set (a
    // step cut back from a set held at a deep first iterate diverged again from it).
    if (contact && contact->pairs)
      contact->pairs->restore();
    if (contact)
      contact->restore();
  }

  template <int dim>
  void FiniteStrainProblem<dim>::set_up_contact()
  {
    contact.reset();
    if (settings.contact.empty() && trim(settings.contact.boundaries).empty())
      return;
    auto obstacles = parse_obstacles<dim>(settings.contact, geometry.boundary_ids, parameters.geometry_parameters);
    std::set<int> rigid_ids; // their nodes are tied to the rigid motion already
    for (const auto &rigid : rigid_boundaries)
      rigid_ids.insert(rigid.load.boundary_id);
    std::set<int> supported_ids; // held by a support: no friction there (its reaction is the support's)
    for (const auto &[name, id] : boundary_conditions.clamped)
      supported_ids.insert(id);
    for (const auto &d : boundary_conditions.displacements) // a roller leaves friction its free directions
      if (std::all_of(d.mask.begin(), d.mask.end(), [](const bool held) { return held; }))
        supported_ids.insert(d.boundary_id);
    for (const auto &r : boundary_conditions.rotations)
      supported_ids.insert(r.boundary_id);
    contact = std::make_unique<ContactSet<dim>>(std::move(obstacles), rigid_ids, supported_ids, dof_handler, *mapping,
                                                *face_quadrature, locally_owned_dofs, locally_relevant_dofs, thickness,
                                                settings.contact.tolerance, communicator);
    const auto pairs = parse_contact_pairs(settings.contact.pairs, geometry.boundary_ids);
    for (const auto &pair : pairs)
      for (const auto &obstacle : contact->obstacles)
        if (obstacle.name == pair.name)
          throw std::invalid_argument("Contact/Pairs: pair '" + pair.name + "' has the name of an obstacle of "
                                      "Contact/Obstacles; their quantities would collide");
    if (!pairs.empty())
      contact->pairs = std::make_unique<ContactPairs<dim>>(pairs, rigid_ids, dof_handler, *mapping, locally_owned_dofs,
                                                           locally_relevant_dofs, thickness, contact->tolerance,
                                                           communicator);
  }

  template <int dim>
  void FiniteStrainProblem<dim>::cover_contact_couplings(const AffineConstraints<double> &constraints) const
  {
    if (!contact || !contact->pairs)
      return;
    std::vector<std::pair<types::global_dof_index, types::global_dof_index>> needed;
    for (const auto &line : constraints.get_lines())
      for (const auto &entry : line.entries)
        needed.emplace_back(line.index, entry.first);
    std::sort(needed.begin(), needed.end());
    const bool covered = std::includes(contact_couplings.begin(), contact_couplings.end(), needed.begin(), needed.end());
    if (Utilities::MPI::min(covered ? 1 : 0, communicator) == 1)
      return;
    reinit_matrix(tangent, dof_handler, constraints, rigid_boundaries, locally_owned_dofs, locally_relevant_dofs,
                  communicator, true);
    contact_couplings = needed;
    if (std::getenv("COMPLIANT_DEBUG_NEWTON") && Utilities::MPI::this_mpi_process(communicator) == 0)
      std::cout << "    contact pairs: tangent pattern rebuilt (" << needed.size() << " couplings)" << std::endl;
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
    return residual_norm_of(rhs);
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
    const HyperelasticLaw law = law_of(material);
    const Tensor<2, dim>  F = unit_symmetric_tensor<dim>() + grad_u;
    const auto            r = material_response(law, green_lagrange(grad_u), pressure, false);
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
    return material_response(law_of(material), green_lagrange(grad_u), 0.0, false).energy;
  }

  template <int dim>
  HyperelasticLaw FiniteStrainProblem<dim>::law_of(const Material &material) const
  {
    // the body's law made at setup (its constants parsed and checked once), else a new one
    for (const auto &[id, m] : materials)
      if (m.name == material.name && m.youngs_modulus == material.youngs_modulus &&
          m.poissons_ratio == material.poissons_ratio && laws.count(id))
        return laws.at(id);
    return HyperelasticLaw(settings.law, material, settings.mooney_rivlin_ratio, settings.law_constants);
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
