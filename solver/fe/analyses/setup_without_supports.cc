#include "analyses/setup_without_supports.h"

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_in.h>

#include "input/spec_list.h"

#include <sstream>

namespace compliant
{
  using namespace dealii;

  bool has_supports(const CaseParameters &p)
  {
    return !trim(p.clamped).empty() || !trim(p.displacement).empty() || !trim(p.rotation).empty();
  }

  template <int dim>
  void setup_without_supports(LinearElasticProblem<dim> &problem)
  {
    Timer       timer;
    const auto &p = problem.parameters;
    if (problem.geometry.dimension != dim)
      throw std::invalid_argument("Model = " + p.model + " needs a " + std::to_string(dim) +
                                  "D mesh, but '" + p.mesh_file + "' is " +
                                  std::to_string(problem.geometry.dimension) + "D");
    {
      GridIn<dim> grid_in;
      grid_in.attach_triangulation(problem.triangulation);
      std::istringstream in(problem.geometry.msh_text);
      grid_in.read_msh(in);
    }
    problem.triangulation.refine_global(p.global_refinements);

    const unsigned int degree = p.element_degree;
    if (problem.triangulation.all_reference_cells_are_hyper_cube())
      {
        problem.fe              = std::make_unique<FESystem<dim>>(FE_Q<dim>(degree), dim);
        problem.mapping         = std::make_unique<MappingQ<dim>>(1);
        problem.quadrature      = std::make_unique<QGauss<dim>>(degree + 1);
        problem.face_quadrature = std::make_unique<QGauss<dim - 1>>(degree + 1);
      }
    else if (problem.triangulation.all_reference_cells_are_simplex())
      {
        problem.fe              = std::make_unique<FESystem<dim>>(FE_SimplexP<dim>(degree), dim);
        problem.mapping         = std::make_unique<MappingFE<dim>>(FE_SimplexP<dim>(1));
        problem.quadrature      = std::make_unique<QGaussSimplex<dim>>(degree + 1);
        problem.face_quadrature = std::make_unique<QGaussSimplex<dim - 1>>(degree + 1);
      }
    else
      throw std::invalid_argument("mesh '" + p.mesh_file + "' mixes cell types");

    problem.materials = assign_materials(p.materials, problem.geometry.material_ids, p.unit_system);
    problem.boundary_conditions = resolve_boundary_conditions<dim>(p, problem.geometry.boundary_ids);

    problem.dof_handler.distribute_dofs(*problem.fe);
    problem.locally_owned_dofs = problem.dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(problem.dof_handler, problem.locally_relevant_dofs);
    problem.constraints.clear();
    problem.constraints.reinit(problem.locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(problem.dof_handler, problem.constraints);
    problem.constraints.close();
    // The sparsity pattern and the matrix follow in install_constraints().
    problem.system_rhs.reinit(problem.locally_owned_dofs, problem.communicator);
    problem.external_forces.reinit(problem.locally_owned_dofs, problem.communicator);
    problem.solution.reinit(problem.locally_owned_dofs, problem.locally_relevant_dofs,
                            problem.communicator);
    problem.statistics.setup_seconds = timer.wall_time();
  }

  template void setup_without_supports<2>(LinearElasticProblem<2> &);
  template void setup_without_supports<3>(LinearElasticProblem<3> &);
} // namespace compliant
