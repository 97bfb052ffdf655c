#include "fast_solver/matrix_free_operator_base.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/sparsity_tools.h>

#include <stdexcept>

namespace compliant::fast_solver
{
  using namespace dealii;

  template <typename Number>
  bool constraints_have_entries(const AffineConstraints<Number> &constraints, MPI_Comm communicator)
  {
    bool entries = false;
    for (const auto &line : constraints.get_lines())
      entries = entries || !line.entries.empty();
    return Utilities::MPI::logical_or(entries, communicator);
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::reinit_matrix_free(const Mapping<dim>              &mapping_in,
                                                               const DoFHandler<dim>           &dof_handler,
                                                               const AffineConstraints<Number> &constraints_in,
                                                               const bool with_reduced_quadrature)
  {
    fe_degree   = dof_handler.get_fe().degree;
    constraints = &constraints_in;
    mapping     = &mapping_in;
    reduced_quadrature = with_reduced_quadrature;
    constraints_have_entries = fast_solver::constraints_have_entries(constraints_in, dof_handler.get_communicator());
    typename MatrixFree<dim, Number, SimdArray<Number>>::AdditionalData additional_data;
    additional_data.tasks_parallel_scheme = MatrixFree<dim, Number, SimdArray<Number>>::AdditionalData::none;
    additional_data.mapping_update_flags  = update_gradients | update_JxW_values;
    data = std::make_shared<MatrixFree<dim, Number, SimdArray<Number>>>();
    std::vector<Quadrature<1>> rules{QGauss<1>(fe_degree + 1)};
    if (with_reduced_quadrature)
      rules.push_back(QGauss<1>(fe_degree));
    data->reinit(mapping_in, std::vector<const DoFHandler<dim> *>{&dof_handler},
                 std::vector<const AffineConstraints<Number> *>{&constraints_in}, rules, additional_data);

    // Every constrained DoF this rank owns gets an identity row: the Krylov vectors stay zero there.
    constrained_local_dofs.clear();
    const auto &partitioner = data->get_vector_partitioner();
    for (const auto index : partitioner->locally_owned_range())
      if (constraints_in.is_constrained(index))
        constrained_local_dofs.push_back(partitioner->global_to_local(index));
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::reinit_layout(const Mapping<dim>              &mapping_in,
                                                          const DoFHandler<dim>           &dof_handler,
                                                          const AffineConstraints<Number> &constraints_in)
  {
    fe_degree   = dof_handler.get_fe().degree;
    constraints = &constraints_in;
    mapping     = &mapping_in;
    constrained_local_dofs.clear();
    typename MatrixFree<dim, Number, SimdArray<Number>>::AdditionalData additional_data;
    additional_data.tasks_parallel_scheme = MatrixFree<dim, Number, SimdArray<Number>>::AdditionalData::none;
    additional_data.initialize_mapping    = false;
    data = std::make_shared<MatrixFree<dim, Number, SimdArray<Number>>>();
    data->reinit(mapping_in, std::vector<const DoFHandler<dim> *>{&dof_handler},
                 std::vector<const AffineConstraints<Number> *>{&constraints_in},
                 std::vector<Quadrature<1>>{QGauss<1>(fe_degree + 1)}, additional_data);
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::vmult(VectorType &dst, const VectorType &src) const
  {
    apply_cells(dst, src, false);
    for (const unsigned int i : constrained_local_dofs)
      dst.local_element(i) = src.local_element(i);
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::vmult_add(VectorType &dst, const VectorType &src) const
  {
    VectorType product;
    initialize_dof_vector(product);
    vmult(product, src);
    dst += product;
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::apply_to_lifting(VectorType &dst, const VectorType &src) const
  {
    apply_cells(dst, src, true);
    for (const unsigned int i : constrained_local_dofs)
      dst.local_element(i) = 0;
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::initialize_dof_vector(VectorType &vector) const
  {
    data->initialize_dof_vector(vector);
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::compute_inverse_diagonal(VectorType &inverse_diagonal) const
  {
    initialize_dof_vector(inverse_diagonal);
    if (constraints_have_entries)
      add_kernel_diagonal(inverse_diagonal);
    else
      add_unconstrained_diagonal(inverse_diagonal);
    for (const unsigned int i : constrained_local_dofs)
      inverse_diagonal.local_element(i) = 1;
    for (auto &value : inverse_diagonal)
      value = value > 0 ? 1 / value : 1;
  }

  template <int dim, typename Number>
  void MatrixFreeOperatorBase<dim, Number>::compute_matrix(PETScWrappers::MPI::SparseMatrix &matrix,
                                                           MPI_Comm communicator) const
  {
    const DoFHandler<dim> &dof_handler = data->get_dof_handler();
    IndexSet               relevant;
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
    DynamicSparsityPattern dsp(relevant);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, *constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp, dof_handler.locally_owned_dofs(), communicator,
                                               relevant);
    matrix.reinit(dof_handler.locally_owned_dofs(), dof_handler.locally_owned_dofs(), dsp, communicator);
    add_kernel_matrix(matrix);
  }

  template <int dim, typename Number>
  types::global_dof_index MatrixFreeOperatorBase<dim, Number>::m() const
  {
    return data->get_vector_partitioner()->size();
  }

  template <int dim, typename Number>
  Number MatrixFreeOperatorBase<dim, Number>::el(const unsigned int, const unsigned int) const
  {
    throw std::logic_error("matrix-free operator: entries are not stored");
  }

  template bool constraints_have_entries(const AffineConstraints<double> &, MPI_Comm);
  template class MatrixFreeOperatorBase<2, double>;
  template class MatrixFreeOperatorBase<3, double>;
} // namespace compliant::fast_solver
