#include "discretization/dof_fingerprint.h"

#include <deal.II/base/mpi.h>

namespace compliant
{
  template <int dim>
  std::vector<double> cell_dof_fingerprint(const dealii::DoFHandler<dim> &dofs, MPI_Comm communicator)
  {
    std::vector<double>                          sums(dim, 0.);
    std::vector<dealii::types::global_dof_index> indices(dofs.get_fe().n_dofs_per_cell());
    for (const auto &cell : dofs.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_indices(indices);
          const dealii::Point<dim> centre = cell->center();
          for (unsigned int i = 0; i < indices.size(); ++i)
            for (unsigned int d = 0; d < dim; ++d)
              sums[d] += (indices[i] + 1.) * (i + 1.) * centre[d];
        }
    dealii::Utilities::MPI::sum(sums, communicator, sums);
    sums.push_back(dofs.n_dofs());
    return sums;
  }

  template <int dim>
  bool numbered_alike(const dealii::DoFHandler<dim> &a, const dealii::DoFHandler<dim> &b, MPI_Comm communicator)
  {
    const bool owned_alike = a.locally_owned_dofs() == b.locally_owned_dofs();
    return dealii::Utilities::MPI::min(owned_alike ? 1 : 0, communicator) == 1 &&
           cell_dof_fingerprint(a, communicator) == cell_dof_fingerprint(b, communicator);
  }

  template std::vector<double> cell_dof_fingerprint<2>(const dealii::DoFHandler<2> &, MPI_Comm);
  template std::vector<double> cell_dof_fingerprint<3>(const dealii::DoFHandler<3> &, MPI_Comm);
  template bool numbered_alike<2>(const dealii::DoFHandler<2> &, const dealii::DoFHandler<2> &, MPI_Comm);
  template bool numbered_alike<3>(const dealii::DoFHandler<3> &, const dealii::DoFHandler<3> &, MPI_Comm);
} // namespace compliant
