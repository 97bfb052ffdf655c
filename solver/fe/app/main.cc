// compliant: a case file in, quantities of interest, closed-form comparison, fields and a JSON
// summary out.   mpirun -np 2 compliant cases/<case>.prm [--set "Section/Name=value"] [--check]
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <closed_forms/registry.h>

#include "elasticity/linear_elastic_problem.h"
#include "input/case_file.h"
#include "output/field_output.h"
#include "output/summary.h"
#include "quantities/comparison.h"
#include "quantities/quantities.h"

#include <filesystem>
#include <iostream>

using namespace compliant;

namespace
{
  void print_help(const dealii::ParameterHandler &prm, bool with_case)
  {
    std::cout << "Usage: mpirun -np N compliant CASE.prm [--set \"Section/Name=value\"]... [--check]\n"
                 "  --help    this text; with a case file, its parameters and current values\n"
                 "  --check   read and validate the case and the mesh, then stop (no output)\n"
                 "  --set     override any parameter, e.g. --set \"Geometry/Parameters/L=5\"\n\n"
              << (with_case ? "Parameters of this case (value, default and documentation):\n" :
                              "Parameters (default and documentation):\n");
    prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
    std::cout << "\nGeometry/Parameters come from the .geo file's DefineConstant[... Name "
                 "\"Parameters/...\"] entries;\ngive a case file to list them.\n\n"
              << material_library_documentation() << "\nClosed forms for Comparison/Checks:\n"
              << closed_forms::documentation();
  }

  // Meshing happens on rank 0; every rank gets the same mesh text, or the same error.
  MeshedGeometry mesh_on_rank_zero(const CaseParameters &p, MPI_Comm comm)
  {
    MeshedGeometry geometry;
    std::string    error;
    if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          geometry = mesh_geometry(p.mesh_file, p.geometry_parameters);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
    error = dealii::Utilities::MPI::broadcast(comm, error, 0);
    if (!error.empty())
      throw InputError("case file '" + p.case_file + "', Geometry/Mesh file: " + error);
    geometry.msh_text     = dealii::Utilities::MPI::broadcast(comm, geometry.msh_text, 0);
    geometry.dimension    = dealii::Utilities::MPI::broadcast(comm, geometry.dimension, 0);
    geometry.boundary_ids = dealii::Utilities::MPI::broadcast(comm, geometry.boundary_ids, 0);
    geometry.material_ids = dealii::Utilities::MPI::broadcast(comm, geometry.material_ids, 0);
    return geometry;
  }

  template <int dim>
  int run(const CaseParameters &p, const MeshedGeometry &geometry, bool check_only, MPI_Comm comm)
  {
    const bool   root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
    dealii::Timer timer;
    LinearElasticProblem<dim> problem(p, geometry, comm);
    const auto requests = parse_checks(p.checks);
    try
      {
        problem.setup();
        validate_quantity_requests(problem);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    if (root)
      std::cout << "Mesh: " << problem.triangulation.n_active_cells() << " cells, "
                << problem.dof_handler.n_dofs() << " DoFs (degree " << p.element_degree << ", "
                << p.model << ") on " << dealii::Utilities::MPI::n_mpi_processes(comm)
                << " ranks" << std::endl;
    if (check_only)
      {
        if (root)
          std::cout << "Case '" << p.case_file << "' is valid." << std::endl;
        return 0;
      }

    problem.assemble();
    problem.solve();
    if (root)
      std::cout << "Solved: " << problem.statistics.iterations << " iterations ("
                << p.solver_method << "), assembly " << problem.statistics.assembly_seconds
                << " s, solve " << problem.statistics.solve_seconds << " s" << std::endl;

    RunSummary summary;
    summary.case_file  = p.case_file;
    summary.settings   = {{"model", p.model},
                        {"mesh_file", p.mesh_file},
                        {"element_degree", std::to_string(p.element_degree)},
                        {"cell_type", problem.triangulation.all_reference_cells_are_hyper_cube() ?
                                        "hypercube" : "simplex"},
                        {"solver", p.solver_method}};
    summary.parameters = p.geometry_parameters;
    summary.quantities = compute_quantities(problem);
    summary.quantities["time_setup"]    = problem.statistics.setup_seconds;
    summary.quantities["time_assembly"] = problem.statistics.assembly_seconds;
    summary.quantities["time_solve"]    = problem.statistics.solve_seconds;

    // Names usable in Derived and Checks expressions.
    auto variables = p.geometry_parameters;
    variables["thickness"] = problem.thickness;
    const Material &first_material = problem.materials.begin()->second;
    variables["E"]  = first_material.youngs_modulus;
    variables["nu"] = first_material.poissons_ratio;
    variables["G"]  = first_material.shear_modulus();
    try
      {
        add_derived_quantities(p.derived, summary.quantities, variables);
        summary.comparisons = run_checks(requests, summary.quantities, variables);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }

    if (root)
      std::filesystem::create_directories(p.output_directory);
    MPI_Barrier(comm);
    if (p.write_fields)
      write_fields(problem, p.output_directory);
    summary.quantities["time_total"] = timer.wall_time();
    if (root)
      {
        write_summary(summary, p.output_directory + "/summary.json");
        std::cout << "\n" << format_table(summary) << "\nResults in " << p.output_directory
                  << "/ (summary.json" << (p.write_fields ? ", fields.xdmf" : "") << ")"
                  << std::endl;
      }
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm   comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  try
    {
      const CommandLine        command_line = parse_command_line(argc, argv);
      dealii::ParameterHandler prm;
      const CaseParameters     p = read_case(command_line, prm);
      if (command_line.help)
        {
          if (root)
            print_help(prm, !p.case_file.empty());
          return 0;
        }
      if (p.case_file.empty())
        throw InputError("no case file given (try --help)");
      const MeshedGeometry geometry = mesh_on_rank_zero(p, comm);
      return p.dimension == 2 ? run<2>(p, geometry, command_line.check, comm) :
                                run<3>(p, geometry, command_line.check, comm);
    }
  catch (const InputError &e)
    {
      if (root)
        std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "error: " << e.what() << std::endl;
      return 1;
    }
}
