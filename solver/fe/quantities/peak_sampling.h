// Shared by the peak quantities (max_von_mises, Region maxima): where peaks are sought, and how a
// peak found on one rank is reported with its location. Internal to solver/fe/quantities.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe.h>

#include <utility>
#include <vector>

namespace compliant
{
  // Quadrature points plus the displacement element's nodes: a bending peak sits on the surface,
  // where the nodes are and the quadrature points are not.
  template <int dim>
  dealii::Quadrature<dim> peak_sample_points(const dealii::Quadrature<dim>    &cell_quadrature,
                                             const dealii::FiniteElement<dim> &fe)
  {
    std::vector<dealii::Point<dim>> points = cell_quadrature.get_points();
    const auto &nodes = fe.base_element(0).get_unit_support_points();
    points.insert(points.end(), nodes.begin(), nodes.end());
    return dealii::Quadrature<dim>(points);
  }

  // The largest of the ranks' local peaks and its location (sent by the rank that holds it).
  template <int dim>
  std::pair<double, dealii::Point<dim>> global_peak(const double              local_value,
                                                    const dealii::Point<dim> &local_location,
                                                    MPI_Comm                  comm)
  {
    const auto             global = dealii::Utilities::MPI::min_max_avg(local_value, comm);
    dealii::Tensor<1, dim> location;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == global.max_index)
      location = local_location;
    location = dealii::Utilities::MPI::sum(location, comm);
    return {global.max, dealii::Point<dim>(location)};
  }
} // namespace compliant
