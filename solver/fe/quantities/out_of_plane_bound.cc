#include "quantities/out_of_plane_bound.h"

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include "elasticity/linear_elastic_problem.h"
#include "linear_algebra/petsc_linear_solver.h"

#include <set>

namespace compliant
{
  OutOfPlaneBound plane_stress_out_of_plane_bound(const LinearElasticProblem<2> &problem)
  {
    using namespace dealii;
    constexpr int dim = 2;
    const auto   &bc  = problem.boundary_conditions;
    const double  b   = problem.thickness;
    MPI_Comm      comm = problem.communicator;

    // psi lives in the scalar space of the displacement's components, on the same mesh.
    DoFHandler<dim> psi_dofs(problem.triangulation);
    psi_dofs.distribute_dofs(problem.fe->base_element(0));
    const IndexSet owned = psi_dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(psi_dofs, relevant);

    // The 3D field must meet the supports: psi = 0 on every edge whose 3D faces a support, a
    // prescribed motion or a rigid boundary holds (u_z = z psi would move them out of plane).
    std::set<types::boundary_id> held;
    for (const auto &[name, id] : bc.clamped)
      held.insert(id);
    for (const auto &d : bc.displacements)
      held.insert(d.boundary_id);
    for (const auto &r : bc.rotations)
      held.insert(r.boundary_id);
    for (const auto &r : bc.rigid)
      held.insert(r.boundary_id);
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(psi_dofs, constraints);
    for (const auto id : held)
      VectorTools::interpolate_boundary_values(*problem.mapping, psi_dofs, id, Functions::ZeroFunction<dim>(),
                                               constraints);
    constraints.close();

    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(psi_dofs, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
    PETScWrappers::MPI::SparseMatrix matrix;
    matrix.reinit(owned, owned, dsp, comm);
    PETScWrappers::MPI::Vector rhs(owned, comm), psi(owned, comm);

    const FEValuesExtractors::Vector displacement(0);
    FEValues<dim> u_values(*problem.mapping, *problem.fe, *problem.quadrature, update_gradients);
    FEValues<dim> psi_values(*problem.mapping, psi_dofs.get_fe(), *problem.quadrature,
                             update_values | update_gradients | update_JxW_values);
    const unsigned int n_q = problem.quadrature->size(), n_dofs = psi_dofs.get_fe().n_dofs_per_cell();
    std::vector<Tensor<2, dim>> grad_u(n_q);
    std::vector<double>         eps_zz(n_q);
    FullMatrix<double>          cell_matrix(n_dofs, n_dofs);
    Vector<double>              cell_rhs(n_dofs);
    std::vector<types::global_dof_index> indices(n_dofs);

    // Per cell: the plane-stress eps_zz at the quadrature points, and the material's moduli.
    const auto out_of_plane_strain = [&](const typename DoFHandler<dim>::active_cell_iterator &cell,
                                         double &stiffness, double &shear) {
      const typename DoFHandler<dim>::active_cell_iterator u_cell(&problem.triangulation, cell->level(),
                                                                  cell->index(), &problem.dof_handler);
      u_values.reinit(u_cell);
      u_values[displacement].get_function_gradients(problem.solution, grad_u);
      const Material &material = problem.materials.at(cell->material_id());
      const double    lambda = material.lame_lambda(), mu = material.shear_modulus();
      stiffness              = lambda + 2 * mu;
      shear                  = mu;
      for (unsigned int q = 0; q < n_q; ++q)
        eps_zz[q] = -lambda / stiffness * trace(grad_u[q]);
    };

    for (const auto &cell : psi_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double stiffness, shear;
          out_of_plane_strain(cell, stiffness, shear);
          psi_values.reinit(cell);
          cell_matrix = 0;
          cell_rhs    = 0;
          for (unsigned int q = 0; q < n_q; ++q)
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                const double phi_i = psi_values.shape_value(i, q), JxW = psi_values.JxW(q);
                for (unsigned int j = 0; j < n_dofs; ++j)
                  cell_matrix(i, j) += (stiffness * phi_i * psi_values.shape_value(j, q) +
                                        shear * b * b / 12 * psi_values.shape_grad(i, q) *
                                          psi_values.shape_grad(j, q)) *
                                       JxW;
                cell_rhs(i) += stiffness * eps_zz[q] * phi_i * JxW;
              }
          cell->get_dof_indices(indices);
          constraints.distribute_local_to_global(cell_matrix, cell_rhs, indices, matrix, rhs);
        }
    matrix.compress(VectorOperation::add);
    rhs.compress(VectorOperation::add);
    LinearSolverSettings settings;
    settings.method = SolverMethod::direct;
    solve_linear_system(matrix, psi, rhs, {}, settings);
    constraints.distribute(psi);
    PETScWrappers::MPI::Vector psi_ghosted(owned, relevant, comm);
    psi_ghosted = psi;

    // dU of this psi (any psi of the space is admissible, the discrete minimiser is the best).
    double              energy = 0;
    std::vector<double> psi_q(n_q);
    std::vector<Tensor<1, dim>> grad_psi(n_q);
    for (const auto &cell : psi_dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          double stiffness, shear;
          out_of_plane_strain(cell, stiffness, shear);
          psi_values.reinit(cell);
          psi_values.get_function_values(psi_ghosted, psi_q);
          psi_values.get_function_gradients(psi_ghosted, grad_psi);
          for (unsigned int q = 0; q < n_q; ++q)
            energy += b *
                      (0.5 * stiffness * (psi_q[q] - eps_zz[q]) * (psi_q[q] - eps_zz[q]) +
                       shear * b * b / 24 * grad_psi[q].norm_square()) *
                      psi_values.JxW(q);
        }
    return {Utilities::MPI::sum(energy, comm), static_cast<unsigned int>(psi_dofs.n_dofs())};
  }
} // namespace compliant
