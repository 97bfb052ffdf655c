// Implementation of ElasticityOperator, included by one translation unit per dimension.
#pragma once

#include "fast_solver/elasticity_operator.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>

#include <stdexcept>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace
  {
    // The cell kernel for one polynomial degree: sigma = lambda tr(eps) I + 2 mu eps at every
    // Gauss point (degree + 1 per direction, exact for affine cells).
    template <int dim, int degree, typename Number>
    struct Kernel
    {
      using Evaluation = FEEvaluation<dim, degree, degree + 1, dim, Number>;
      using VectorType = LinearAlgebra::distributed::Vector<Number>;

      static void stress_at_quadrature_points(Evaluation &phi, const VectorizedArray<Number> &lambda,
                                              const VectorizedArray<Number> &mu)
      {
        phi.evaluate(EvaluationFlags::gradients);
        for (unsigned int q = 0; q < phi.n_q_points; ++q)
          {
            const SymmetricTensor<2, dim, VectorizedArray<Number>> eps = phi.get_symmetric_gradient(q);
            SymmetricTensor<2, dim, VectorizedArray<Number>> sigma = (mu + mu) * eps;
            const VectorizedArray<Number> lambda_trace = lambda * trace(eps);
            for (unsigned int d = 0; d < dim; ++d)
              sigma[d][d] += lambda_trace;
            phi.submit_symmetric_gradient(sigma, q);
          }
        phi.integrate(EvaluationFlags::gradients);
      }

      static void apply(const MatrixFree<dim, Number> &data, VectorType &dst, const VectorType &src,
                        const std::pair<unsigned int, unsigned int> &range,
                        const std::vector<VectorizedArray<Number>>   &lambda,
                        const std::vector<VectorizedArray<Number>>   &mu, const bool plain)
      {
        Evaluation phi(data);
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

      static void diagonal(const MatrixFree<dim, Number> &data, VectorType &diagonal,
                           const std::vector<VectorizedArray<Number>> &lambda,
                           const std::vector<VectorizedArray<Number>> &mu)
      {
        MatrixFreeTools::compute_diagonal<dim, degree, degree + 1, dim, Number, VectorizedArray<Number>>(
          data, diagonal, [&](Evaluation &phi) {
            const unsigned int cell = phi.get_current_cell_index();
            stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
          });
      }

      static void matrix(const MatrixFree<dim, Number> &data, const AffineConstraints<Number> &constraints,
                         PETScWrappers::MPI::SparseMatrix &matrix,
                         const std::vector<VectorizedArray<Number>> &lambda,
                         const std::vector<VectorizedArray<Number>> &mu)
      {
        MatrixFreeTools::compute_matrix<dim, degree, degree + 1, dim, Number, VectorizedArray<Number>>(
          data, constraints, matrix, [&](Evaluation &phi) {
            const unsigned int cell = phi.get_current_cell_index();
            stress_at_quadrature_points(phi, lambda[cell], mu[cell]);
          });
      }
    };

    // Runs F<degree>::call(args...) for the run-time degree (1-4: the element degrees offered).
    template <int dim, typename Number, typename Visitor>
    void dispatch(const unsigned int degree, const Visitor &visitor)
    {
      switch (degree)
        {
          case 1: visitor(Kernel<dim, 1, Number>()); break;
          case 2: visitor(Kernel<dim, 2, Number>()); break;
          case 3: visitor(Kernel<dim, 3, Number>()); break;
          case 4: visitor(Kernel<dim, 4, Number>()); break;
          default:
            throw std::invalid_argument("matrix-free elasticity: element degree " +
                                        std::to_string(degree) + " is not compiled (1-4)");
        }
    }
  } // namespace

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::reinit(const Mapping<dim>              &mapping_in,
                                               const DoFHandler<dim>           &dof_handler,
                                               const AffineConstraints<Number> &constraints_in,
                                               const LameParameters            &lame)
  {
    fe_degree   = dof_handler.get_fe().degree;
    constraints = &constraints_in;
    mapping     = &mapping_in;
    constraints_have_entries = false;
    for (const auto &line : constraints_in.get_lines())
      if (!line.entries.empty())
        constraints_have_entries = true;
    constraints_have_entries = Utilities::MPI::logical_or(constraints_have_entries,
                                                          dof_handler.get_communicator());
    typename MatrixFree<dim, Number>::AdditionalData additional_data;
    additional_data.tasks_parallel_scheme = MatrixFree<dim, Number>::AdditionalData::none;
    additional_data.mapping_update_flags  = update_gradients | update_JxW_values;
    data = std::make_shared<MatrixFree<dim, Number>>();
    data->reinit(mapping_in, dof_handler, constraints_in, QGauss<1>(fe_degree + 1), additional_data);

    const unsigned int n_batches = data->n_cell_batches();
    lambda.assign(n_batches, VectorizedArray<Number>());
    mu.assign(n_batches, VectorizedArray<Number>());
    for (unsigned int batch = 0; batch < n_batches; ++batch)
      for (unsigned int lane = 0; lane < data->n_active_entries_per_cell_batch(batch); ++lane)
        {
          const auto [l, m] = lame(data->get_cell_iterator(batch, lane)->material_id());
          lambda[batch][lane] = l;
          mu[batch][lane]     = m;
        }

    // Every constrained DoF this rank owns gets an identity row: the Krylov vectors stay zero there.
    constrained_local_dofs.clear();
    const auto &partitioner = data->get_vector_partitioner();
    for (const auto index : partitioner->locally_owned_range())
      if (constraints_in.is_constrained(index))
        constrained_local_dofs.push_back(partitioner->global_to_local(index));
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::apply_cells(VectorType &dst, const VectorType &src,
                                                    const bool plain) const
  {
    dispatch<dim, Number>(fe_degree, [&](auto kernel) {
      using K = decltype(kernel);
      data->template cell_loop<VectorType, VectorType>(
        [&](const MatrixFree<dim, Number> &mf, VectorType &d, const VectorType &s,
            const std::pair<unsigned int, unsigned int> &range) {
          K::apply(mf, d, s, range, lambda, mu, plain);
        },
        dst, src, true);
    });
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::vmult(VectorType &dst, const VectorType &src) const
  {
    apply_cells(dst, src, false);
    for (const unsigned int i : constrained_local_dofs)
      dst.local_element(i) = src.local_element(i);
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::vmult_add(VectorType &dst, const VectorType &src) const
  {
    VectorType product;
    initialize_dof_vector(product);
    vmult(product, src);
    dst += product;
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::apply_to_lifting(VectorType &dst, const VectorType &src) const
  {
    apply_cells(dst, src, true);
    for (const unsigned int i : constrained_local_dofs)
      dst.local_element(i) = 0;
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::initialize_dof_vector(VectorType &vector) const
  {
    data->initialize_dof_vector(vector);
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::compute_inverse_diagonal(VectorType &inverse_diagonal) const
  {
    initialize_dof_vector(inverse_diagonal);
    if (constraints_have_entries)
      dispatch<dim, Number>(fe_degree, [&](auto kernel) {
        decltype(kernel)::diagonal(*data, inverse_diagonal, lambda, mu);
      });
    else
      add_unconstrained_diagonal(inverse_diagonal);
    for (const unsigned int i : constrained_local_dofs)
      inverse_diagonal.local_element(i) = 1;
    for (auto &value : inverse_diagonal)
      value = value > 0 ? 1 / value : 1;
  }

  template <int dim, typename Number>
  void ElasticityOperator<dim, Number>::add_unconstrained_diagonal(VectorType &diagonal) const
  {
    // Shape function i has one nonzero component c: eps_i : eps_i = (|grad phi|^2 + d_c phi^2) / 2
    // and div phi_i = d_c phi, so K_ii = sum_q JxW (mu |grad phi|^2 + (lambda + mu) d_c phi^2).
    const DoFHandler<dim>  &dof_handler = data->get_dof_handler();
    const auto             &fe          = dof_handler.get_fe();
    FEValues<dim>           fe_values(*mapping, fe, QGauss<dim>(fe_degree + 1),
                            update_gradients | update_JxW_values);
    const unsigned int      n = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    for (unsigned int batch = 0; batch < data->n_cell_batches(); ++batch)
      for (unsigned int lane = 0; lane < data->n_active_entries_per_cell_batch(batch); ++lane)
        {
          const auto cell = data->get_cell_iterator(batch, lane);
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
  void ElasticityOperator<dim, Number>::compute_matrix(PETScWrappers::MPI::SparseMatrix &matrix,
                                                       MPI_Comm communicator) const
  {
    const DoFHandler<dim> &dof_handler = data->get_dof_handler();
    IndexSet               relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, *constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, dof_handler.locally_owned_dofs(), communicator,
                                               relevant);
    matrix.reinit(dof_handler.locally_owned_dofs(), dof_handler.locally_owned_dofs(), dsp,
                  communicator);
    dispatch<dim, Number>(fe_degree, [&](auto kernel) {
      decltype(kernel)::matrix(*data, *constraints, matrix, lambda, mu);
    });
  }

  template <int dim, typename Number>
  types::global_dof_index ElasticityOperator<dim, Number>::m() const
  {
    return data->get_vector_partitioner()->size();
  }

  template <int dim, typename Number>
  Number ElasticityOperator<dim, Number>::el(const unsigned int, const unsigned int) const
  {
    throw std::logic_error("ElasticityOperator::el: entries are not stored");
  }

} // namespace compliant::fast_solver
