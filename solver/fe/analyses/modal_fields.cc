#include "analyses/modal_fields.h"
#include "output/field_writer.h"

#include <deal.II/base/quadrature.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>

#include <cmath>
#include <cstdio>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // Largest displacement magnitude at the support points of the owned cells, over all ranks.
    template <int dim>
    double largest_magnitude(const Discretization<dim>         &problem,
                             const PETScWrappers::MPI::Vector &ghosted)
    {
      // The displacement element's nodes (a mixed element's pressure has none).
      const Quadrature<dim> support(problem.fe->base_element(0).get_unit_support_points());
      FEValues<dim>         fe_values(*problem.mapping, *problem.fe, support, update_values);
      std::vector<Vector<double>> values(support.size(), Vector<double>(problem.fe->n_components()));
      double                      largest = 0;
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            fe_values.get_function_values(ghosted, values);
            for (const auto &v : values)
              {
                double squared = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  squared += v[d] * v[d];
                largest = std::max(largest, std::sqrt(squared));
              }
          }
      return Utilities::MPI::max(largest, problem.communicator);
    }
  } // namespace

  template <int dim>
  std::string write_mode_shapes(const Discretization<dim>                     &problem,
                                const std::vector<PETScWrappers::MPI::Vector> &modes,
                                const std::string                             &directory)
  {
    DataOut<dim> data_out;
    data_out.attach_dof_handler(problem.dof_handler);
    // Displacement, and with the mixed formulation the pressure of the mode (a scalar).
    std::vector<DataComponentInterpretation::DataComponentInterpretation> interpretation(
      dim, DataComponentInterpretation::component_is_part_of_vector);
    if (problem.fe->n_components() > dim)
      interpretation.push_back(DataComponentInterpretation::component_is_scalar);
    std::vector<PETScWrappers::MPI::Vector> scaled;
    scaled.reserve(modes.size()); // DataOut keeps references
    for (unsigned int m = 0; m < modes.size(); ++m)
      {
        scaled.emplace_back(problem.locally_owned_dofs, problem.locally_relevant_dofs,
                            problem.communicator);
        scaled.back() = modes[m];
        const double largest = largest_magnitude(problem, scaled.back());
        PETScWrappers::MPI::Vector owned(modes[m]);
        if (largest > 0)
          owned /= largest;
        scaled.back() = owned;
        std::vector<std::string> names(dim, "mode_" + std::to_string(m + 1));
        if (problem.fe->n_components() > dim)
          names.push_back("mode_" + std::to_string(m + 1) + "_pressure");
        data_out.add_data_vector(scaled.back(), names, DataOut<dim>::type_dof_data, interpretation);
      }
    return write_field_files(data_out, problem, directory);
  }

  template std::string write_mode_shapes<2>(const Discretization<2> &,
                                            const std::vector<PETScWrappers::MPI::Vector> &,
                                            const std::string &);
  template std::string write_mode_shapes<3>(const Discretization<3> &,
                                            const std::vector<PETScWrappers::MPI::Vector> &,
                                            const std::string &);
} // namespace compliant
