// Geometry/Imperfection: the perfect geometry's linear buckling modes under the case's loads, each
// scaled so that its largest displacement component is the named amplitude, summed into a shift
// of the geometry that the nonlinear run's mapping takes on (discretization/geometry_imperfection.h).
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/petsc_vector.h>

#include "analyses/buckling_parts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>

namespace compliant
{
  namespace
  {
    using Vector = dealii::PETScWrappers::MPI::Vector;

    // +1 or -1: the sign that makes the mode's largest displacement component positive; where a
    // positive and a negative one are equally large (to 1e-6), the one at the smallest x, y, z.
    template <int dim>
    double orientation(const LinearElasticProblem<dim> &problem, const Vector &mode, double &largest)
    {
      MPI_Comm     comm = problem.communicator;
      const auto  &fe   = *problem.fe;
      double       most = 0, least = 0; // largest and smallest displacement component
      std::vector<dealii::types::global_dof_index> indices(fe.n_dofs_per_cell());
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              if (fe.system_to_component_index(i).first < dim)
                {
                  most  = std::max(most, mode(indices[i]));
                  least = std::min(least, mode(indices[i]));
                }
          }
      most    = dealii::Utilities::MPI::max(most, comm);
      least   = dealii::Utilities::MPI::min(least, comm);
      largest = std::max(most, -least);
      if (std::abs(most + least) > 1e-6 * largest)
        return most > -least ? 1. : -1.;

      // A tie: the first position in x, y, z order among the largest components decides.
      std::array<double, 4> first{{HUGE_VAL, HUGE_VAL, HUGE_VAL, 0.}}; // x, y, z, sign
      for (const auto &cell : problem.dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            cell->get_dof_indices(indices);
            for (unsigned int i = 0; i < indices.size(); ++i)
              {
                const auto base = fe.system_to_base_index(i);
                if (fe.system_to_component_index(i).first >= dim || !(std::abs(mode(indices[i])) >= (1 - 1e-6) * largest))
                  continue;
                const auto x = problem.mapping->transform_unit_to_real_cell(
                  cell, fe.base_element(base.first.first).unit_support_point(base.second));
                std::array<double, 4> here{{x[0], x[1], dim == 3 ? x[dim - 1] : 0., mode(indices[i]) > 0 ? 1. : -1.}};
                if (std::lexicographical_compare(here.begin(), here.begin() + 3, first.begin(), first.begin() + 3))
                  first = here;
              }
          }
      for (const auto &other : dealii::Utilities::MPI::all_gather(comm, first))
        if (std::lexicographical_compare(other.begin(), other.begin() + 3, first.begin(), first.begin() + 3))
          first = other;
      return first[3];
    }
  } // namespace

  template <int dim>
  std::shared_ptr<const GeometryImperfection> buckling_mode_imperfection(const RunContext &context, Quantities &q)
  {
    const auto &p    = context.parameters;
    MPI_Comm    comm = context.communicator;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    if (context.check_only || p.imperfection.empty())
      return nullptr;
    BucklingSettings settings = read_buckling_settings(context.prm);
    settings.n_modes          = 0;
    for (const auto &m : p.imperfection)
      settings.n_modes = std::max(settings.n_modes, m.mode);
    if (root)
      std::cout << "Imperfection: linear buckling of the perfect geometry under the case's loads" << std::endl;
    if (root && p.rigid.find_first_not_of(" \t\r\n") != std::string::npos)
      std::cout << "Imperfection: linear buckling leaves out the rigid pieces' geometric stiffness: the "
                   "shapes serve as imperfections, their load factors are approximate" << std::endl;
    auto buckling = solve_linear_buckling<dim>(context, settings);
    auto &problem = *buckling.model.problem;
    auto  modes   = add_buckling_factors(buckling.result, 0, q, root, buckling.eigen_seconds);
    distribute_support_constraints(problem, modes);

    const auto &fe           = *problem.fe;
    auto        imperfection = std::make_shared<GeometryImperfection>();
    imperfection->degree     = fe.base_element(0).degree;
    const dealii::FESystem<dim> shift_fe(dealii::FE_Q<dim>(imperfection->degree), dim);
    std::vector<double>         local(fe.n_dofs_per_cell());
    for (const auto &cell : problem.dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        imperfection->cell_shift[cell->id()].assign(shift_fe.n_dofs_per_cell(), 0.);
    for (const auto &m : p.imperfection)
      {
        Vector mode(problem.locally_owned_dofs, problem.locally_relevant_dofs, comm);
        mode = modes[m.mode - 1];
        double       largest = 0;
        const double sign    = orientation(problem, mode, largest);
        if (!(largest > 0))
          throw InputError("case file '" + p.case_file + "', Geometry/Imperfection: buckling mode " +
                           std::to_string(m.mode) + " has no displacement");
        const double scale = sign * m.amplitude / largest;
        q["imperfection_amplitude_" + std::to_string(m.mode)] = m.amplitude;
        for (const auto &cell : problem.dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_values(mode, local.begin(), local.end());
              auto &shift = imperfection->cell_shift[cell->id()];
              for (unsigned int i = 0; i < local.size(); ++i)
                {
                  const auto component = fe.system_to_component_index(i);
                  if (component.first < dim)
                    shift[shift_fe.component_to_system_index(component.first, component.second)] += scale * local[i];
                }
            }
        if (root)
          std::cout << "Imperfection: mode " << m.mode << " (load factor "
                    << q["buckling_factor_" + std::to_string(m.mode)] << ") scaled to " << m.amplitude << std::endl;
      }
    return imperfection;
  }

  template std::shared_ptr<const GeometryImperfection> buckling_mode_imperfection<2>(const RunContext &, Quantities &);
  template std::shared_ptr<const GeometryImperfection> buckling_mode_imperfection<3>(const RunContext &, Quantities &);
} // namespace compliant
