// The tangent stiffness of the finite-strain problem as a matrix in its own right: assembled at the
// current state (buckling about a nonlinear state, the stability count), its action (the check of the
// matrix-free operator against the assembled one) and its consistency with the residual.
#include "finite_strain/finite_strain_problem.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/lac/la_parallel_vector.h>

#include "fast_solver/tangent_operator.h"
#include "linear_algebra/direct_factorization.h"
#include "linear_algebra/petsc_linear_solver.h"

namespace compliant
{
  using namespace dealii;

  template <int dim>
  const PETScWrappers::MPI::SparseMatrix &
  FiniteStrainProblem<dim>::assemble_tangent(AffineConstraints<double> &homogeneous) const
  {
    homogeneous = make_constraints(load_factor, true, solution);
    PETScWrappers::MPI::Vector rhs(locally_owned_dofs, communicator);
    assemble(solution, load_factor, &homogeneous, true, rhs);
    return tangent;
  }

  template <int dim>
  unsigned int FiniteStrainProblem<dim>::unstable_modes() const
  {
    AffineConstraints<double> homogeneous;
    assemble_tangent(homogeneous);
    const unsigned int negative = count_negative_eigenvalues(tangent);
    // K_pp = -M/lambda is negative definite: inertia(K) = inertia(K_pp) + inertia(Schur complement)
    const auto per_component = DoFTools::count_dofs_per_fe_component(dof_handler);
    const unsigned int n_pressure = mixed ? per_component.back() : 0;
    return negative > n_pressure ? negative - n_pressure : 0;
  }

  template <int dim>
  PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::tangent_action(const PETScWrappers::MPI::Vector &u,
                                                                      const PETScWrappers::MPI::Vector &v,
                                                                      const double lambda,
                                                                      const bool   matrix_free) const
  {
    PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
    PETScWrappers::MPI::Vector product(locally_owned_dofs, communicator);
    ghosted = u;
    AffineConstraints<double> constraints;
    constraints.reinit(locally_relevant_dofs);
    add_level_constraints(dof_handler, constraints);
    constraints.close();
    if (!matrix_free)
      {
        PETScWrappers::MPI::Vector rhs(locally_owned_dofs, communicator);
        assemble(ghosted, lambda, &constraints, true, rhs);
        tangent.vmult(product, v);
      }
    else
      {
        fast_solver::TangentOperator<dim, double> op;
        op.reinit(*mapping, dof_handler, constraints,
                  parameters.reduced_integration ? parameters.hourglass_stiffness : -1.);
        op.set_state(dof_handler, ghosted,
                     [this](const types::material_id id, const Tensor<2, dim> &grad_u,
                            SymmetricTensor<2, dim> &S, SymmetricTensor<4, dim> &dS_dE) {
                       const auto r = material_response(laws.at(id), green_lagrange(grad_u), 0.0);
                       S            = thickness * r.S;
                       dS_dE        = thickness * r.tangent;
                     });
        LinearAlgebra::distributed::Vector<double> src, dst;
        op.initialize_dof_vector(src);
        op.initialize_dof_vector(dst);
        for (const auto i : locally_owned_dofs)
          src(i) = v(i);
        op.vmult(dst, src);
        for (const auto i : locally_owned_dofs)
          product(i) = dst(i);
        product.compress(VectorOperation::insert);
      }
    // Constrained rows differ by construction (identity against a scaled diagonal): compare
    // the free rows only.
    for (const auto i : locally_owned_dofs)
      if (constraints.is_constrained(i))
        product(i) = 0;
    product.compress(VectorOperation::insert);
    return product;
  }

  template <int dim>
  double FiniteStrainProblem<dim>::tangent_consistency(const PETScWrappers::MPI::Vector &u,
                                                       const PETScWrappers::MPI::Vector &v,
                                                       const double lambda, const double h) const
  {
    AffineConstraints<double> none;
    none.close();
    PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
    PETScWrappers::MPI::Vector rhs(locally_owned_dofs, communicator), Kv(rhs);
    ghosted = u;
    assemble(ghosted, lambda, &none, true, rhs);
    tangent.vmult(Kv, v);
    PETScWrappers::MPI::Vector difference = central_difference(u, v, lambda, h, nullptr);
    difference.add(-1, Kv);
    return difference.l2_norm() / Kv.l2_norm();
  }

  template <int dim>
  PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::tangent_times(const PETScWrappers::MPI::Vector &psi,
                                                                     const AffineConstraints<double> &homogeneous) const
  {
    // A step small against the state's displacements and the cells (central differences: error
    // h^2), the same on every rank.
    const double scale = std::max(solution.linfty_norm(), 1e-3 * GridTools::minimal_cell_diameter(triangulation));
    const double h     = 1e-6 * scale / std::max(psi.linfty_norm(), 1e-300);
    return central_difference(solution, psi, load_factor, h, &homogeneous);
  }

  template <int dim>
  PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::central_difference(const PETScWrappers::MPI::Vector &u,
                                                                          const PETScWrappers::MPI::Vector &v,
                                                                          const double lambda, const double h,
                                                                          const AffineConstraints<double> *constraints) const
  {
    PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
    PETScWrappers::MPI::Vector state(locally_owned_dofs, communicator), plus(state), minus(state);
    state = u;
    state.add(h, v);
    ghosted = state;
    assemble(ghosted, lambda, constraints, false, plus);
    state.add(-2 * h, v);
    ghosted = state;
    assemble(ghosted, lambda, constraints, false, minus);
    // assemble gives f_ext - f_int: K v = (R(u - h v) - R(u + h v)) / 2h
    PETScWrappers::MPI::Vector product = minus;
    product.add(-1, plus);
    product /= 2 * h;
    return product;
  }

  template <int dim>
  std::function<PETScWrappers::MPI::Vector(PETScWrappers::MPI::Vector)>
  FiniteStrainProblem<dim>::tangent_dual_solver(AffineConstraints<double> &homogeneous) const
  {
    assemble_tangent(homogeneous);
    auto factor = std::make_shared<DirectFactorization>();
    factor->factor(tangent, false);
    const AffineConstraints<double> *held = &homogeneous;
    return [this, factor, held](PETScWrappers::MPI::Vector j) {
      for (const auto i : locally_owned_dofs)
        if (held->is_constrained(i))
          j(i) = 0;
      j.compress(VectorOperation::insert);
      PETScWrappers::MPI::Vector z(locally_owned_dofs, communicator);
      factor->solve_transpose(z, j); // K_T^T z = j: the tangent is unsymmetric under follower loads
      held->distribute(z);
      PETScWrappers::MPI::Vector ghosted(locally_owned_dofs, locally_relevant_dofs, communicator);
      ghosted = z;
      return ghosted;
    };
  }

#define INSTANTIATE(dim)                                                                                       \
  template const PETScWrappers::MPI::SparseMatrix &FiniteStrainProblem<dim>::assemble_tangent(                 \
    AffineConstraints<double> &) const;                                                                        \
  template unsigned int               FiniteStrainProblem<dim>::unstable_modes() const;                        \
  template double                     FiniteStrainProblem<dim>::tangent_consistency(                           \
    const PETScWrappers::MPI::Vector &, const PETScWrappers::MPI::Vector &, double, double) const;             \
  template PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::tangent_action(                                \
    const PETScWrappers::MPI::Vector &, const PETScWrappers::MPI::Vector &, double, bool) const;              \
  template PETScWrappers::MPI::Vector FiniteStrainProblem<dim>::tangent_times(                                 \
    const PETScWrappers::MPI::Vector &, const AffineConstraints<double> &) const;                              \
  template std::function<PETScWrappers::MPI::Vector(PETScWrappers::MPI::Vector)>                             \
  FiniteStrainProblem<dim>::tangent_dual_solver(AffineConstraints<double> &) const;
  INSTANTIATE(2)
  INSTANTIATE(3)
#undef INSTANTIATE
} // namespace compliant
