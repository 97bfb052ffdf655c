// Implementation of TangentOperator, included by one translation unit per dimension.
#pragma once

#include "fast_solver/tangent_operator.h"
#include "fast_solver/integration_rules.h"
#include "fast_solver/subspace_matrix.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/matrix_free/fe_evaluation.h>
#include <deal.II/matrix_free/tools.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant::fast_solver
{
  using namespace dealii;

  namespace tangent_detail
  {
    // One Gauss rule (n_q points per direction, MatrixFree rule `quad`) with its share `scale`:
    // the full rule alone (scale 1), or with reduced integration the reduced rule (1 - e) and the
    // full one (e).
    template <int dim, int degree, int n_q, typename Number>
    struct Kernel
    {
      using Evaluation = FEEvaluation<dim, degree, n_q, dim, Number, SimdArray<Number>>;
      using VectorType = LinearAlgebra::distributed::Vector<Number>;
      using State      = typename TangentOperator<dim, Number>::PointState;

      unsigned int quad  = 0;
      Number       scale = 1;

      // dP = Grad du S + F (dS/dE : sym(F^T Grad du)) at every Gauss point of the batch.
      void at_quadrature_points(Evaluation &phi, const State *point) const
      {
        phi.evaluate(EvaluationFlags::gradients);
        for (unsigned int q = 0; q < phi.n_q_points; ++q)
          {
            const auto &s  = point[q];
            const auto  H  = phi.get_gradient(q);
            const auto  dE = symmetrize(transpose(s.F) * H);
            const auto  dS = s.dS_dE * dE;
            phi.submit_gradient(scale * (H * Tensor<2, dim, SimdArray<Number>>(s.S) +
                                         s.F * Tensor<2, dim, SimdArray<Number>>(dS)),
                                q);
          }
        phi.integrate(EvaluationFlags::gradients);
      }

      void apply(const MatrixFree<dim, Number, SimdArray<Number>> &data, VectorType &dst, const VectorType &src,
                 const std::pair<unsigned int, unsigned int> &range, const AlignedVector<State> &state,
                 const bool plain) const
      {
        Evaluation phi(data, 0, quad);
        for (unsigned int cell = range.first; cell < range.second; ++cell)
          {
            phi.reinit(cell);
            if (plain)
              phi.read_dof_values_plain(src);
            else
              phi.read_dof_values(src);
            at_quadrature_points(phi, &state[cell * phi.n_q_points]);
            phi.distribute_local_to_global(dst);
          }
      }

      void diagonal(const MatrixFree<dim, Number, SimdArray<Number>> &data, VectorType &diagonal, const AlignedVector<State> &state) const
      {
        MatrixFreeTools::compute_diagonal<dim, degree, n_q, dim, Number, SimdArray<Number>>(
          data, diagonal,
          [&](Evaluation &phi) { at_quadrature_points(phi, &state[phi.get_current_cell_index() * phi.n_q_points]); },
          0, quad);
      }

      void matrix(const MatrixFree<dim, Number, SimdArray<Number>> &data, const AffineConstraints<Number> &constraints,
                  PETScWrappers::MPI::SparseMatrix &matrix, const AlignedVector<State> &state) const
      {
        MatrixFreeTools::compute_matrix<dim, degree, n_q, dim, Number, SimdArray<Number>>(
          data, constraints, matrix,
          [&](Evaluation &phi) { at_quadrature_points(phi, &state[phi.get_current_cell_index() * phi.n_q_points]); },
          0, quad);
      }

      // Adds this rule's share of the long-edge space's Galerkin matrix.
      void subspace_matrix(const MatrixFree<dim, Number, SimdArray<Number>> &data, const LongEdgeSpace &space,
                           Mat matrix, const AlignedVector<State> &state) const
      {
        add_subspace_matrix<dim, degree, n_q, Number>(data, quad, space, matrix, [&](Evaluation &phi) {
          at_quadrature_points(phi, &state[phi.get_current_cell_index() * phi.n_q_points]);
        });
      }
    };
  } // namespace tangent_detail

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::reinit(const Mapping<dim>              &mapping_in,
                                            const DoFHandler<dim>           &dof_handler,
                                            const AffineConstraints<Number> &constraints_in,
                                            const double                     hourglass_stiffness)
  {
    reduced   = hourglass_stiffness >= 0 && dof_handler.get_fe().degree >= 2;
    hourglass = reduced ? hourglass_stiffness : 0;
    this->reinit_matrix_free(mapping_in, dof_handler, constraints_in, reduced);
    n_q_points = {{Utilities::pow(this->fe_degree + 1, dim), reduced ? Utilities::pow(this->fe_degree, dim) : 0u}};
    // Undeformed and stress-free: F = I, S = 0 (the tangent then has no stiffness until set_state).
    PointState undeformed;
    for (unsigned int d = 0; d < dim; ++d)
      undeformed.F[d][d] = 1;
    for (unsigned int r = 0; r < 2; ++r)
      {
        state[r].resize_fast(this->data->n_cell_batches() * n_q_points[r]);
        for (auto &point : state[r])
          point = undeformed;
      }
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::set_state(const DoFHandler<dim>            &state_dofs,
                                               const PETScWrappers::MPI::Vector &u,
                                               const PointResponse<dim>         &response)
  {
    bool finite = true;
    for (unsigned int r = 0; r < (reduced ? 2u : 1u); ++r)
      {
        // FEValues on the state's element at this level's Gauss points: the points come in the
        // same (lexicographic tensor-product) order as in FEEvaluation.
        const QGauss<dim>                quadrature(this->fe_degree + 1 - r);
        FEValues<dim>                    values(*this->mapping, state_dofs.get_fe(), quadrature, update_gradients);
        const FEValuesExtractors::Vector displacement(0);
        const unsigned int               n_q = n_q_points[r];
        std::vector<Tensor<2, dim>>      grad_u(n_q);
        SymmetricTensor<2, dim>          S;
        SymmetricTensor<4, dim>          dS_dE;
        for (unsigned int batch = 0; batch < this->data->n_cell_batches(); ++batch)
          for (unsigned int lane = 0; lane < this->data->n_active_entries_per_cell_batch(batch); ++lane)
            {
              const auto level_cell = this->data->get_cell_iterator(batch, lane);
              const typename DoFHandler<dim>::active_cell_iterator cell(&state_dofs.get_triangulation(),
                                                                        level_cell->level(),
                                                                        level_cell->index(), &state_dofs);
              values.reinit(cell);
              values[displacement].get_function_gradients(u, grad_u);
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  response(cell->material_id(), grad_u[q], S, dS_dE);
                  finite      = finite && std::isfinite(S.norm()) && std::isfinite(dS_dE.norm());
                  auto &point = state[r][batch * n_q + q];
                  for (unsigned int i = 0; i < dim; ++i)
                    for (unsigned int j = 0; j < dim; ++j)
                      {
                        point.F[i][j][lane] = (i == j ? 1.0 : 0.0) + grad_u[q][i][j];
                        if (j >= i)
                          point.S[i][j][lane] = S[i][j];
                        for (unsigned int k = 0; k < dim; ++k)
                          for (unsigned int l = k; l < dim; ++l)
                            if (j >= i)
                              point.dS_dE[i][j][k][l][lane] = dS_dE[i][j][k][l];
                      }
                }
            }
      }
    if (Utilities::MPI::logical_or(!finite, this->data->get_dof_handler().get_communicator()))
      throw std::runtime_error("matrix-free tangent: the law gives no finite stress at a Gauss "
                               "point of the degree-" + std::to_string(this->fe_degree) + " level");
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::apply_cells(VectorType &dst, const VectorType &src,
                                                 const bool plain) const
  {
    this->data->template cell_loop<VectorType, VectorType>(
      [&](const MatrixFree<dim, Number, SimdArray<Number>> &mf, VectorType &d, const VectorType &s,
          const std::pair<unsigned int, unsigned int> &range) {
        for_each_rule<tangent_detail::Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
          kernel.apply(mf, d, s, range, state[kernel.quad], plain);
        });
      },
      dst, src, true);
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::add_kernel_diagonal(VectorType &diagonal) const
  {
    for_each_rule<tangent_detail::Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
      kernel.diagonal(*this->data, diagonal, state[kernel.quad]);
    });
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::add_unconstrained_diagonal(VectorType &diagonal) const
  {
    // Shape function i has one nonzero component c with gradient g: Grad phi = e_c (x) g,
    // sym(F^T Grad phi) = sym(f (x) g) with f the row c of F, and the geometric part is g.S.g.
    const DoFHandler<dim> &dof_handler = this->data->get_dof_handler();
    const auto            &fe          = dof_handler.get_fe();
    const unsigned int     n           = fe.n_dofs_per_cell();
    std::vector<types::global_dof_index> dofs(n);
    for (unsigned int r = 0; r < (reduced ? 2u : 1u); ++r)
      {
        const double  share = !reduced ? 1. : r == 0 ? hourglass : 1 - hourglass;
        const auto   &rule  = state[r];
        const unsigned int n_q = n_q_points[r];
        FEValues<dim> fe_values(*this->mapping, fe, QGauss<dim>(this->fe_degree + 1 - r),
                                update_gradients | update_JxW_values);
        std::vector<Tensor<2, dim>>          F(n_q);
        std::vector<SymmetricTensor<2, dim>> S(n_q);
        std::vector<SymmetricTensor<4, dim>> C(n_q);
        for (unsigned int batch = 0; batch < this->data->n_cell_batches(); ++batch)
          for (unsigned int lane = 0; lane < this->data->n_active_entries_per_cell_batch(batch); ++lane)
            {
              const auto cell = this->data->get_cell_iterator(batch, lane);
              fe_values.reinit(cell);
              cell->get_dof_indices(dofs);
              for (unsigned int q = 0; q < n_q; ++q)
                {
                  const auto &point = rule[batch * n_q + q];
                  for (unsigned int a = 0; a < dim; ++a)
                    for (unsigned int b = 0; b < dim; ++b)
                      {
                        F[q][a][b] = point.F[a][b][lane];
                        if (b < a)
                          continue;
                        S[q][a][b] = point.S[a][b][lane];
                        for (unsigned int k = 0; k < dim; ++k)
                          for (unsigned int l = k; l < dim; ++l)
                            C[q][a][b][k][l] = point.dS_dE[a][b][k][l][lane];
                      }
                }
              for (unsigned int i = 0; i < n; ++i)
                {
                  const unsigned int c     = fe.system_to_component_index(i).first;
                  double             value = 0;
                  for (unsigned int q = 0; q < n_q; ++q)
                    {
                      const Tensor<1, dim>    g = fe_values.shape_grad_component(i, q, c);
                      SymmetricTensor<2, dim> dE;
                      for (unsigned int a = 0; a < dim; ++a)
                        for (unsigned int b = a; b < dim; ++b)
                          dE[a][b] = 0.5 * (F[q][c][a] * g[b] + F[q][c][b] * g[a]);
                      value += (dE * (C[q] * dE) + g * (S[q] * g)) * fe_values.JxW(q);
                    }
                  diagonal(dofs[i]) += share * value;
                }
            }
      }
    diagonal.compress(VectorOperation::add);
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::add_kernel_matrix(PETScWrappers::MPI::SparseMatrix &matrix) const
  {
    for_each_rule<tangent_detail::Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
      kernel.matrix(*this->data, *this->constraints, matrix, state[kernel.quad]);
    });
  }

  template <int dim, typename Number>
  void TangentOperator<dim, Number>::add_kernel_subspace_matrix(const LongEdgeSpace &space, Mat matrix) const
  {
    for_each_rule<tangent_detail::Kernel, dim, Number>(this->fe_degree, reduced, hourglass, [&](const auto &kernel) {
      kernel.subspace_matrix(*this->data, space, matrix, state[kernel.quad]);
    });
  }
} // namespace compliant::fast_solver
