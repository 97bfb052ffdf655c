#include "elasticity/linear_elastic_problem.h"
#include "linear_algebra/direct_factorization.h"

#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgp.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include "elasticity/rigid_rotation.h"
#include "fast_solver/elasticity_operator.h"
#include "fast_solver/p_multigrid_solver.h"
#include "input/expression.h"
#include "linear_algebra/rigid_body_modes.h"
#include "elasticity/von_mises.h"
#include "mesh/curved_simplex_mapping.h"
#include "mesh/mesh_reader.h"
#include "linear_algebra/petsc_linear_solver.h"

#include <deal.II/lac/solver_control.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // A displacement function (dim components) seen with the mixed element's extra pressure
    // component, which it leaves at zero.
    template <int dim>
    class ExtendedFunction : public Function<dim>
    {
    public:
      ExtendedFunction(const Function<dim> &displacement, const unsigned int n_components)
        : Function<dim>(n_components)
        , displacement(displacement)
      {}
      double value(const Point<dim> &p, const unsigned int component) const override
      {
        return component < displacement.n_components ? displacement.value(p, component) : 0.0;
      }
      void vector_value(const Point<dim> &p, Vector<double> &values) const override
      {
        Vector<double> u(displacement.n_components);
        displacement.vector_value(p, u);
        values = 0;
        for (unsigned int c = 0; c < u.size(); ++c)
          values[c] = u[c];
      }

    private:
      const Function<dim> &displacement;
    };

    template <int dim>
    using ExpressionFields = std::map<int, std::unique_ptr<FunctionParser<dim>>>; // per boundary id

    // Loads/Traction expressions, each evaluated once so that a bad one fails before assembly.
    template <int dim>
    ExpressionFields<dim> make_traction_fields(const std::map<int, std::vector<std::string>> &traction_fields,
                                               const std::map<std::string, double>           &constants)
    {
      ExpressionFields<dim> fields;
      for (const auto &[id, expressions] : traction_fields)
        fields[id] = make_field_function<dim>(expressions, constants, "Loads/Traction");
      return fields;
    }

    // Loads/Pressure expressions, likewise; the error names the boundary as the case file does.
    template <int dim>
    ExpressionFields<dim> make_pressure_fields(const std::map<int, std::string>    &pressures,
                                               const std::map<std::string, double> &constants,
                                               const std::map<std::string, int>    &boundary_ids)
    {
      ExpressionFields<dim> fields;
      for (const auto &[id, expression] : pressures)
        {
          std::string boundary = std::to_string(id);
          for (const auto &[name, boundary_id] : boundary_ids)
            if (boundary_id == id)
              boundary = name;
          fields[id] = make_field_function<dim>({expression}, constants, "Loads/Pressure on '" + boundary + "'");
        }
      return fields;
    }

    // The local stiffness and loads of one cell, with the scratch every cell reuses (allocated
    // once, outside the cell loop).
    template <int dim>
    class ElasticCellAssembler
    {
    public:
      ElasticCellAssembler(const LinearElasticProblem<dim> &problem, bool with_matrix);

      // Resets cell_matrix (lower triangle mirrored: it is symmetric) and cell_rhs to the
      // cell's stiffness, or the mixed u-p block matrix, and its body force.
      void add_volume_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                            const Material &material, const Tensor<1, dim> &body_force);
      // Adds tractions (constant, total force, expressions) and pressure on boundary faces.
      void add_boundary_terms(const typename DoFHandler<dim>::active_cell_iterator &cell,
                              const std::map<int, Tensor<1, dim>>                  &tractions,
                              const ExpressionFields<dim>                          &traction_fields,
                              const ExpressionFields<dim>                          &pressure_fields);

      FullMatrix<double>                   cell_matrix;
      Vector<double>                       cell_rhs;
      std::vector<types::global_dof_index> dofs;

    private:
      const LinearElasticProblem<dim>     &problem; // for stress(): the constitutive law in one place
      const bool                           with_matrix, mixed;
      const double                         thickness;
      FEValues<dim>                        fe_values;
      FEFaceValues<dim>                    fe_face_values;
      const FEValuesExtractors::Vector     u;
      const FEValuesExtractors::Scalar     pressure;
      Vector<double>                       field_value;
      const unsigned int                   n;
      std::vector<SymmetricTensor<2, dim>> eps;
      std::vector<double>                  divergence, pressure_value;
    };

    template <int dim>
    ElasticCellAssembler<dim>::ElasticCellAssembler(const LinearElasticProblem<dim> &problem,
                                                    const bool                       with_matrix)
      : cell_matrix(problem.fe->n_dofs_per_cell(), problem.fe->n_dofs_per_cell())
      , cell_rhs(problem.fe->n_dofs_per_cell())
      , dofs(problem.fe->n_dofs_per_cell())
      , problem(problem)
      , with_matrix(with_matrix)
      , mixed(problem.mixed)
      , thickness(problem.thickness)
      , fe_values(*problem.mapping, *problem.fe, *problem.quadrature,
                  update_gradients | update_values | update_JxW_values)
      , fe_face_values(*problem.mapping, *problem.fe, *problem.face_quadrature,
                       update_values | update_JxW_values | update_quadrature_points | update_normal_vectors)
      , u(0)
      , pressure(problem.mixed ? dim : 0)
      , field_value(dim)
      , n(problem.fe->n_dofs_per_cell())
      , eps(n)
      , divergence(n)
      , pressure_value(n)
    {}

    template <int dim>
    void ElasticCellAssembler<dim>::add_volume_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const Material                                       &material,
      const Tensor<1, dim>                                 &body_force)
    {
      cell_matrix = 0;
      cell_rhs    = 0;
      fe_values.reinit(cell);
      for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
        {
          const double JxW = fe_values.JxW(q) * thickness;
          if (with_matrix)
            for (unsigned int i = 0; i < n; ++i)
              eps[i] = fe_values[u].symmetric_gradient(i, q);
          if (with_matrix && mixed)
            {
              // (2 mu eps(u), eps(v)) - (p, div v) - (q, div u) - (p q) / lambda
              const double mu = material.shear_modulus(), lambda = material.lame_lambda();
              for (unsigned int i = 0; i < n; ++i)
                {
                  divergence[i]     = fe_values[u].divergence(i, q);
                  pressure_value[i] = fe_values[pressure].value(i, q);
                }
              for (unsigned int i = 0; i < n; ++i)
                for (unsigned int j = 0; j <= i; ++j)
                  cell_matrix(i, j) += (2 * mu * (eps[i] * eps[j]) - divergence[i] * pressure_value[j] -
                                        pressure_value[i] * divergence[j] -
                                        pressure_value[i] * pressure_value[j] / lambda) *
                                       JxW;
            }
          for (unsigned int i = 0; i < n; ++i)
            {
              if (with_matrix && !mixed)
                {
                  double     sigma_zz;
                  const auto sigma_i = problem.stress(eps[i], material, sigma_zz);
                  for (unsigned int j = 0; j <= i; ++j)
                    cell_matrix(i, j) += (sigma_i * eps[j]) * JxW;
                }
              cell_rhs(i) += fe_values[u].value(i, q) * body_force * JxW;
            }
        }
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = i + 1; j < n; ++j)
          cell_matrix(i, j) = cell_matrix(j, i);
    }

    template <int dim>
    void ElasticCellAssembler<dim>::add_boundary_terms(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const std::map<int, Tensor<1, dim>>                  &tractions,
      const ExpressionFields<dim>                          &traction_fields,
      const ExpressionFields<dim>                          &pressure_fields)
    {
      for (const auto f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const int  id             = cell->face(f)->boundary_id();
            const auto t              = tractions.find(id);
            const auto field          = traction_fields.find(id);
            const auto pressure_field = pressure_fields.find(id);
            if (t == tractions.end() && field == traction_fields.end() &&
                pressure_field == pressure_fields.end())
              continue;
            fe_face_values.reinit(cell, f);
            for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
              {
                Tensor<1, dim> traction = t != tractions.end() ? t->second : Tensor<1, dim>();
                if (field != traction_fields.end())
                  {
                    field->second->vector_value(fe_face_values.quadrature_point(q), field_value);
                    for (unsigned int d = 0; d < dim; ++d)
                      traction[d] += field_value[d];
                  }
                if (pressure_field != pressure_fields.end())
                  traction -= pressure_field->second->value(fe_face_values.quadrature_point(q)) *
                              fe_face_values.normal_vector(q);
                for (unsigned int i = 0; i < n; ++i)
                  cell_rhs(i) += fe_face_values[u].value(i, q) * traction *
                                 fe_face_values.JxW(q) * thickness;
              }
          }
    }
  } // namespace

  template <int dim>
  LinearElasticProblem<dim>::LinearElasticProblem(const CaseParameters &parameters,
                                                  const MeshedGeometry &geometry,
                                                  MPI_Comm              communicator,
                                                  const MeshPartitionChoice &partition)
    : Discretization<dim>(parameters, geometry, communicator, partition)
  {}

  template <int dim>
  void LinearElasticProblem<dim>::setup()
  {
    Timer timer;
    setup_discretization();
    if (boundary_conditions.clamped.empty() && boundary_conditions.displacements.empty() &&
        boundary_conditions.rotations.empty())
      throw std::invalid_argument("Boundary conditions: nothing is clamped, displaced or rotated; "
                                  "a linear static solve needs the rigid-body motion constrained");
    make_constraints();
    choose_solver_method();
    if (solver_method != SolverMethod::matrix_free)
      allocate_matrix();
    statistics.setup_seconds = timer.wall_time();
  }

  template <int dim>
  void LinearElasticProblem<dim>::allocate_matrix()
  {
    reinit_matrix(system_matrix, dof_handler, constraints, rigid_boundaries, locally_owned_dofs, locally_relevant_dofs,
                  communicator);
  }

  template <int dim>
  void LinearElasticProblem<dim>::setup_discretization()
  {
    this->check_mesh_dimension();
    this->create_mesh();
    this->choose_element(false);
    mixed = parameters.formulation == Formulation::mixed;
    if (mixed)
      {
        if (plane_stress)
          throw std::invalid_argument("Discretization/Formulation = mixed: plane stress does not lock "
                                      "(the thickness strain takes up the volume change); use "
                                      "displacement, or plane strain or 3d");
        if (!triangulation.all_reference_cells_are_hyper_cube() || parameters.element_degree < 2)
          throw std::invalid_argument("Discretization/Formulation = mixed needs quadrilaterals or "
                                      "hexahedra and Element degree 2 or 3 (Q2-P1, Q3-P2)");
        this->choose_element(true);
      }
    this->assign_materials();
    this->resolve_boundary_conditions();
    this->distribute_dofs();
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    constraints.copy_from(hanging_node_constraints);
    rigid_boundaries.clear();
    for (const auto &load : boundary_conditions.rigid)
      rigid_boundaries.emplace_back(load, dof_handler, *mapping, hanging_node_constraints, communicator);
    system_rhs.reinit(locally_owned_dofs, communicator);
    external_forces.reinit(locally_owned_dofs, communicator);
    solution.reinit(locally_owned_dofs, locally_relevant_dofs, communicator);
  }

  template <int dim>
  void LinearElasticProblem<dim>::make_constraints()
  {
    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    add_support_constraints(dof_handler, constraints, false);
    for (const auto &rigid : rigid_boundaries)
      rigid.add_constraints(constraints); // refuses nodes a support holds
    constraints.close();
  }

  template <int dim>
  void LinearElasticProblem<dim>::add_support_constraints(const DoFHandler<dim>     &dofs,
                                                          AffineConstraints<double> &constraints,
                                                          const bool homogeneous) const
  {
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    // Functions of the displacement only; a mixed element's pressure is never constrained.
    const unsigned int                 n_components = dofs.get_fe().n_components();
    const Functions::ZeroFunction<dim> zero(n_components);
    std::vector<bool>                  displacement_only(n_components, false);
    std::fill(displacement_only.begin(), displacement_only.begin() + dim, true);
    const ComponentMask displacement_mask(displacement_only);
    // First condition wins on shared edges/corners: clamped, then displacement, then rotation.
    for (const auto &[name, id] : boundary_conditions.clamped)
      VectorTools::interpolate_boundary_values(*mapping, dofs, id, zero, constraints, displacement_mask);
    for (const auto &d : boundary_conditions.displacements)
      {
        auto expressions = d.expressions;
        expressions.resize(n_components, "0");
        const auto field = make_field_function<dim>(expressions, parameters.geometry_parameters,
                                                    "Boundary conditions/Displacement of '" + d.boundary + "'");
        VectorTools::interpolate_boundary_values(*mapping, dofs, d.boundary_id,
                                                 homogeneous ? static_cast<const Function<dim> &>(zero) :
                                                               *field,
                                                 constraints, [&] {
                                                   std::vector<bool> mask = d.mask;
                                                   mask.resize(n_components, false);
                                                   return ComponentMask(mask);
                                                 }());
      }
    for (const auto &r : boundary_conditions.rotations)
      {
        const RigidRotation<dim> rotation(r.angle, r.center, r.axis);
        const ExtendedFunction<dim> padded(rotation, n_components);
        VectorTools::interpolate_boundary_values(*mapping, dofs, r.boundary_id,
                                                 homogeneous ? static_cast<const Function<dim> &>(zero) :
                                                               padded,
                                                 constraints, displacement_mask);
      }
  }

  template <int dim>
  double LinearElasticProblem<dim>::boundary_measure(int boundary_id) const
  {
    FEFaceValues<dim> fe_face_values(*mapping, *fe, *face_quadrature, update_JxW_values);
    double            measure = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto f : cell->face_indices())
          if (cell->face(f)->at_boundary() && (int)cell->face(f)->boundary_id() == boundary_id)
            {
              fe_face_values.reinit(cell, f);
              for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
                measure += fe_face_values.JxW(q);
            }
    return Utilities::MPI::sum(measure, communicator);
  }

  template <int dim>
  std::map<int, Tensor<1, dim>> LinearElasticProblem<dim>::boundary_tractions() const
  {
    auto tractions = boundary_conditions.tractions;
    for (const auto &[name, force] : boundary_conditions.total_forces)
      {
        const int id = geometry.boundary_ids.at(name);
        tractions[id] += force / (boundary_measure(id) * thickness);
      }
    return tractions;
  }

  template <int dim>
  SymmetricTensor<2, dim> LinearElasticProblem<dim>::stress(const SymmetricTensor<2, dim> &strain,
                                                            const Material &material,
                                                            double         &sigma_zz) const
  {
    const double mu     = material.shear_modulus();
    double       lambda = material.lame_lambda();
    if (dim == 2 && parameters.model == Model::plane_stress)
      lambda = 2 * lambda * mu / (lambda + 2 * mu);
    const double trace = dealii::trace(strain);
    sigma_zz = (dim == 2 && parameters.model == Model::plane_strain) ? material.lame_lambda() * trace : 0;
    return lambda * trace * unit_symmetric_tensor<dim>() + 2 * mu * strain;
  }

  template <int dim>
  double LinearElasticProblem<dim>::von_mises(const SymmetricTensor<2, dim> &s, const double sigma_zz) const
  {
    return von_mises_stress(s, sigma_zz);
  }

  template <int dim>
  void LinearElasticProblem<dim>::assemble()
  {
    Timer timer;
    factorization.reset(); // of the matrix assembled before
    // The matrix-free solver needs only C^T f; it moves prescribed values to the right side itself.
    const bool with_matrix = solver_method != SolverMethod::matrix_free;
    if (with_matrix)
      system_matrix = 0;
    system_rhs      = 0;
    external_forces = 0;
    const auto tractions       = boundary_tractions(); // collective (boundary measures)
    const auto traction_fields = make_traction_fields<dim>(boundary_conditions.traction_fields,
                                                           parameters.geometry_parameters);
    const auto pressure_fields = make_pressure_fields<dim>(boundary_conditions.pressures,
                                                           parameters.geometry_parameters,
                                                           geometry.boundary_ids);

    ElasticCellAssembler<dim> cells(*this, with_matrix);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const Material &material = materials.at(cell->material_id());
          const auto body_force = boundary_conditions.body_force + material.density * boundary_conditions.gravity;
          cells.add_volume_terms(cell, material, body_force);
          cells.add_boundary_terms(cell, tractions, traction_fields, pressure_fields);
          cell->get_dof_indices(cells.dofs);
          // C^T f: on adaptive meshes a hanging DoF's share belongs to its masters (reactions).
          hanging_node_constraints.distribute_local_to_global(cells.cell_rhs, cells.dofs, external_forces);
          if (with_matrix)
            constraints.distribute_local_to_global(cells.cell_matrix, cells.cell_rhs, cells.dofs, system_matrix,
                                                   system_rhs);
          else
            constraints.distribute_local_to_global(cells.cell_rhs, cells.dofs, system_rhs);
        }
    for (const auto &rigid : rigid_boundaries)
      {
        rigid.add_load(1, &constraints, system_rhs);
        rigid.add_load(1, nullptr, external_forces);
      }
    if (with_matrix)
      system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
    external_forces.compress(VectorOperation::add);
    // A load expression that divides by zero somewhere gives NaN or infinity: say so here, not as
    // a failed (or crashed) solve.
    if (!std::isfinite(external_forces.l2_norm()))
      throw std::invalid_argument("Loads: the loads are not finite (NaN or infinity) somewhere on "
                                  "the loaded boundaries or bodies: check the expressions of "
                                  "Loads/Traction, Loads/Pressure, Loads/Body force and Loads/Total force");
    statistics.assembly_seconds = timer.wall_time();
  }


  template <int dim>
  SymmetricTensor<2, dim> LinearElasticProblem<dim>::cauchy_stress(const Tensor<2, dim> &grad_u,
                                                                   const Material &material,
                                                                   const double    pressure,
                                                                   double         &sigma_zz) const
  {
    if (!mixed)
      return stress(symmetrize(grad_u), material, sigma_zz);
    // sigma = 2 mu eps - p I; in plane strain eps_zz = 0, so sigma_zz = -p.
    sigma_zz = dim == 2 ? -pressure : 0;
    return 2 * material.shear_modulus() * symmetrize(grad_u) - pressure * unit_symmetric_tensor<dim>();
  }

  template <int dim>
  double LinearElasticProblem<dim>::energy_density(const Tensor<2, dim> &grad_u,
                                                   const Material       &material,
                                                   const double          pressure) const
  {
    double     sigma_zz;
    const auto strain = symmetrize(grad_u);
    if (mixed) // 0.5 (2 mu eps : eps + p^2 / lambda), with div u = -p / lambda weakly
      return 0.5 * (2 * material.shear_modulus() * (strain * strain) +
                    pressure * pressure / material.lame_lambda());
    return 0.5 * (stress(strain, material, sigma_zz) * strain);
  }

  template <int dim>
  PETScWrappers::MPI::Vector LinearElasticProblem<dim>::reaction_forces() const
  {
    // The system matrix has the Dirichlet rows condensed away, so f_int is assembled afresh.
    PETScWrappers::MPI::Vector residual(locally_owned_dofs, communicator);
    FEValues<dim> fe_values(*mapping, *fe, *quadrature, update_values | update_gradients | update_JxW_values);
    const FEValuesExtractors::Vector     u(0);
    const unsigned int                   n = fe->n_dofs_per_cell();
    Vector<double>                       cell_vector(n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<Tensor<2, dim>>          grad(fe_values.n_quadrature_points);
    std::vector<double>                  p_values(fe_values.n_quadrature_points, 0.0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_gradients(solution, grad);
          if (mixed)
            fe_values[FEValuesExtractors::Scalar(dim)].get_function_values(solution, p_values);
          const Material &material = materials.at(cell->material_id());
          cell_vector              = 0;
          for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
            {
              double     sigma_zz;
              const auto sigma = cauchy_stress(grad[q], material, p_values[q], sigma_zz);
              for (unsigned int i = 0; i < n; ++i)
                cell_vector(i) +=
                  (sigma * fe_values[u].symmetric_gradient(i, q)) * fe_values.JxW(q) * thickness;
            }
          cell->get_dof_indices(dofs);
          // Condensed like external_forces: a reaction on a boundary with hanging nodes is the
          // sum over its masters (raw residuals at hanging DoFs are not forces on the support).
          hanging_node_constraints.distribute_local_to_global(cell_vector, dofs, residual);
        }
    residual.compress(VectorOperation::add);
    residual -= external_forces;
    return residual;
  }


  template class LinearElasticProblem<2>;
  template class LinearElasticProblem<3>;
} // namespace compliant
