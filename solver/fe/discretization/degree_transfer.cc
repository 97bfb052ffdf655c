#include "discretization/degree_transfer.h"

#include <deal.II/fe/fe_tools.h>
#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace compliant
{
  template <int dim>
  bool interpolate_to_finer_degree(const Discretization<dim>                &from,
                                   const dealii::PETScWrappers::MPI::Vector &field,
                                   const Discretization<dim>                &to,
                                   dealii::PETScWrappers::MPI::Vector       &result)
  {
    const auto &fe_from = *from.fe, &fe_to = *to.fe;
    bool        same = from.triangulation.n_global_active_cells() == to.triangulation.n_global_active_cells() &&
                fe_from.n_components() == fe_to.n_components() && fe_from.reference_cell() == fe_to.reference_cell() &&
                fe_from.degree <= fe_to.degree;
    dealii::FullMatrix<double> interpolation(fe_to.n_dofs_per_cell(), fe_from.n_dofs_per_cell());
    // Elements without support points (the discontinuous P_p pressure of the mixed formulation)
    // by the L2 projection on the reference cell, which is exact for nested spaces too.
    if (same && fe_from.has_support_points() && fe_to.has_support_points())
      dealii::FETools::get_interpolation_matrix(fe_from, fe_to, interpolation);
    else if (same)
      dealii::FETools::get_projection_matrix(fe_from, fe_to, interpolation);
    std::vector<dealii::types::global_dof_index> indices_from(fe_from.n_dofs_per_cell()),
      indices_to(fe_to.n_dofs_per_cell()), owned_indices;
    dealii::Vector<double> values_from(fe_from.n_dofs_per_cell()), values_to(fe_to.n_dofs_per_cell());
    std::vector<double>    owned_values;
    auto                   cell_to = to.dof_handler.begin_active();
    for (auto cell_from = from.dof_handler.begin_active(); same && cell_from != from.dof_handler.end();
         ++cell_from, ++cell_to)
      {
        if (cell_to == to.dof_handler.end() || cell_from->id() != cell_to->id() ||
            cell_from->is_locally_owned() != cell_to->is_locally_owned() ||
            cell_from->center().distance(cell_to->center()) > 1e-12 * cell_from->diameter())
          {
            same = false;
            break;
          }
        if (!cell_from->is_locally_owned())
          continue;
        cell_from->get_dof_values(field, values_from);
        interpolation.vmult(values_to, values_from);
        cell_to->get_dof_indices(indices_to);
        // A shared node gets the same value from every cell (the field is continuous).
        for (unsigned int i = 0; i < indices_to.size(); ++i)
          if (to.locally_owned_dofs.is_element(indices_to[i]))
            owned_indices.push_back(indices_to[i]), owned_values.push_back(values_to[i]);
      }
    same = dealii::Utilities::MPI::min(same ? 1 : 0, to.communicator) == 1;
    if (!same)
      return false;
    result.reinit(to.locally_owned_dofs, to.communicator);
    result.set(owned_indices, owned_values);
    result.compress(dealii::VectorOperation::insert);
    return true;
  }

  template bool interpolate_to_finer_degree<2>(const Discretization<2> &, const dealii::PETScWrappers::MPI::Vector &,
                                               const Discretization<2> &, dealii::PETScWrappers::MPI::Vector &);
  template bool interpolate_to_finer_degree<3>(const Discretization<3> &, const dealii::PETScWrappers::MPI::Vector &,
                                               const Discretization<3> &, dealii::PETScWrappers::MPI::Vector &);
} // namespace compliant
