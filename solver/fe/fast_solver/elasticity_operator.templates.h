// Implementation of ElasticityOperator, included by one translation unit per dimension.
#pragma once

#include "fast_solver/elasticity_operator.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>

#include "discretization/reduced_integration.h"
#include "fast_solver/integration_rules.h"
#include "fast_solver/subspace_matrix.h"

#include <stdexcept>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace
  {
    // The cell kernel for one polynomial degree and one Gauss rule (n_q points per direction,
    // MatrixFree rule `quad`): sigma = scale (lambda tr(eps) I + 2 mu eps) at every point. Full
    // integration is n_q = degree + 1 with scale 1 (exact for affine cells); reduced integration adds
    // n_q = degree with scale 1 - e to n_q = degree + 1 with scale e.
    template <int dim, int degree, int n_q, typename Number>
    struct Kernel
    {
      using Evaluation = FEEvaluation<dim, degree, n_q, dim, Number, SimdArray<Number>>;
      using VectorType = LinearAlgebra::distributed::Vector<Number>;

      unsigned int quad  = 0;
      Number       scale = 1;

      void stress_at_quadrature_points(Evaluation &phi, const SimdArray<Number> &lambda,
                                       const SimdArray<Number> &mu) const
      {
        phi.evaluate(EvaluationFlags::gradients);
        const SimdArray<Number> two_mu = 2 * scale * mu, l = scale * lambda;
        for (unsigned int q = 0; q < phi.n_q_points; ++q)
          {
            const SymmetricTensor<2, dim, SimdArray<Number>> eps = phi.get_symmetric_gradient(q);
            SymmetricTensor<2, dim, SimdArray<Number>> sigma = two_mu * eps;
            const SimdArray<Number> lambda_trace = l * trace(eps);
            for (unsigned int d = 0; d < dim; ++d)
              sigma[d][d] += lambda_trace;
            phi.submit_symmetric_gradient(sigma, q);
          }
        phi.integrate(EvaluationFlags::gradients);
      }

      void apply(const MatrixFree<dim, Number, SimdArray<Number>> &data, VectorType &dst, const VectorType &src,
                 const std::pair<unsigned int, unsigned int> &range,
                 const std::vector<SimdArray<Number>>   &lambda,
                 const std::vector<SimdArray<Number>>   &mu, const bool plain) const
      {
        Evaluation phi(data, 0, quad);
        for (unsigned int cell = range.first; cell < range.second; ++cell)
          {
            phi.reinit(cell);
            if (plain)
              phi.read_dof_values_plain(src);
            else
              phi.read_dof_values(src);
            stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
            phi.distribute_local_to_global(dst);
          }
      }

      // Adds this rule's share to `diagonal`.
      void diagonal(const MatrixFree<dim, Number, SimdArray<Number>> &data, VectorType &diagonal,
                    const std::vector<SimdArray<Number>> &lambda,
                    const std::vector<SimdArray<Number>> &mu) const
      {
        MatrixFreeTools::compute_diagonal<dim, degree, n_q, dim, Number, SimdArray<Number>>(
          data, diagonal,
          [&](Evaluation &phi) {
            const unsigned int cell = phi.get_current_cell_index();
            stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
          },
          0, quad);
      }

      // Adds this rule's share to `matrix`.
      void matrix(const MatrixFree<dim, Number, SimdArray<Number>> &data, const AffineConstraints<Number> &constraints,
                  PETScWrappers::MPI::SparseMatrix &matrix,
                  const std::vector<SimdArray<Number>> &lambda,
                  const std::vector<SimdArray<Number>> &mu) const
      {
        MatrixFreeTools::compute_matrix<dim, degree, n_q, dim, Number, SimdArray<Number>>(
          data, constraints, matrix,
          [&](Evaluation &phi) {
            const unsigned int cell = phi.get_current_cell_index();
            stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
          },
          0, quad);
      }

      // Adds this rule's share of the long-edge space's Galerkin matrix.
      void subspace_matrix(const MatrixFree<dim, Number, SimdArray<Number>> &data, const LongEdgeSpace &space,
                           Mat matrix, const std::vector<SimdArray<Number>> &lambda,
                           const std::vector<SimdArray<Number>> &mu) const
      {
        add_subspace_matrix<dim, degree, n_q, Number>(data, quad, space, matrix, [&](Evaluation &phi) {
          const unsigned int cell = phi.get_current_cell_index();
          stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
        });
      }
    };
  } // namespace

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::reinit(const Mapping<dim>              &mapping_in,
                                               const DoFHandler<dim>           &dof_handler,
                                               const AffineConstraints<Number> &constraints_in,
                                               const LameParameters            &lame,
                                               const double                     hourglass_stiffness)
  {
    reduced   = hourglass_stiffness >= 0 && dof_handler.get_fe().degree >= 2;
    hourglass = reduced ? hourglass_stiffness : 0;
    this->reinit_matrix_free(mapping_in, dof_handler, constraints_in, reduced);
    const auto        &data      = *this->data;
    const unsigned int n_batches = data.n_cell_batches();
    lambda.assign(n_batches, SimdArray<Number>());
    mu.assign(n_batches, SimdArray<Number>());
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int lane = 0; lane < data.n_active_entries_per_cell_batch(batch); ++lane)
        {
          const auto [l, m] = lame(data.get_cell_iterator(batch, lane)->material_id());
          lambda[batch][lane] = l;
          mu[batch][lane]     = m;
        }
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::apply_cells(VectorType &dst, const VectorType &src,
                                                    const bool plain) const
  {
    this->data->template cell_loop<VectorType, VectorType>(
      [&](const MatrixFree<dim, Number, SimdArray<Number>> &mf, VectorType &d, const VectorType &s,
          const std::pair<unsigned int, unsigned int> &range) {
        for_each_rule<Kernel, dim, Number>(this->fe_degree, reduced, hourglass,
                                   [&](const auto &kernel) { kernel.apply(mf, d, s, range, lambda, mu, plain); });
      },
      dst, src, true);
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::add_kernel_diagonal(VectorType &diagonal) const
  {
    for_each_rule<Kernel, dim, Number>(this->fe_degree, reduced, hourglass,
                               [&](const auto &kernel) { kernel.diagonal(*this->data, diagonal, lambda, mu); });
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::add_unconstrained_diagonal(VectorType &diagonal) const
  {
    // Shape function i has one nonzero component c: eps_i : eps_i = (|grad phi|^2 + d_c phi^2) / 2
    // and div phi_i = d_c phi, so K_ii = sum_q JxW (mu |grad phi|^2 + (lambda + mu) d_c phi^2).
    const DoFHandler<dim>  &dof_handler = this->data->get_dof_handler();
    const auto             &fe          = dof_handler.get_fe();
    const Quadrature<dim>   rule = reduced ? stabilized_reduced_quadrature<dim>(this->fe_degree, hourglass) :
                                         Quadrature<dim>(QGauss<dim>(this->fe_degree + 1));
    FEValues<dim>           fe_values(*this->mapping, fe, rule, update_gradients | update_JxW_values);
    const unsigned int      n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    for (unsigned int batch = 0; batch < this->data->n_cell_batches(); ++batch)
      for (unsigned int lane = 0; lane < this->data->n_active_entries_per_cell_batch(batch); ++lane)
        {
          const auto cell = this->data->get_cell_iterator(batch, lane);
          fe_values.reinit(cell);
          cell->get_dof_indices(dofs);
          const double l = lambda[batch][lane], m = mu[batch][lane];
          for (unsigned int i = 0; i < n; ++i)
            {
              const unsigned int c     = fe.system_to_component_index(i).first;
              double             value = 0;
              for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
                {
                  const Tensor<1, dim> grad = fe_values.shape_grad_component(i, q, c);
                  value += (m * grad.norm_square() + (l + m) * grad[c] * grad[c]) * fe_values.JxW(q);
                }
              diagonal(dofs[i]) += value;
            }
        }
    diagonal.compress(VectorOperation::add);
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::add_kernel_matrix(PETScWrappers::MPI::SparseMatrix &matrix) const
  {
    for_each_rule<Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
      kernel.matrix(*this->data, *this->constraints, matrix, lambda, mu);
    });
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::add_kernel_subspace_matrix(const LongEdgeSpace &space, Mat matrix) const
  {
    for_each_rule<Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
      kernel.subspace_matrix(*this->data, space, matrix, lambda, mu);
    });
  }
} // namespace compliant::fast_solver
