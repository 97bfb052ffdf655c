// compliant: a case file in, quantities of interest, closed-form comparison, fields and a JSON
// summary out.   mpirun -np 2 compliant cases/<case>.prm [--set "Section/Name=value"] [--check]
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <closed_forms/registry.h>

#include "analyses/analysis.h"
#include "elasticity/material.h"
#include "input/case_file.h"

#include <chrono>
#include <cstdlib>
#include <iostream>
#include <thread>

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

  void report_curved_boundaries(const CurvedEntities &curved)
  {
    if (!curved.exact.empty())
      {
        const char *names[] = {"circle", "cylinder", "sphere"};
        unsigned int counts[3] = {0, 0, 0};
        for (const auto &boundary : curved.exact)
          ++counts[boundary.shape];
        std::cout << "Curved boundaries:";
        for (unsigned int s = 0; s < 3; ++s)
          if (counts[s] > 0)
            std::cout << " " << counts[s] << " " << names[s] << (counts[s] > 1 ? "s" : "");
        std::cout << " follow the geometry; cells mapped at the element degree\n";
      }
    for (const auto &entity : curved.straightened)
      std::cout << "Curved boundaries: " << entity
                << " is neither circle, cylinder nor sphere: its faces stay straight\n";
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
          if (!p.curved_boundaries)
            geometry.curved = {};
          report_curved_boundaries(geometry.curved);
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
    geometry.n_cells      = dealii::Utilities::MPI::broadcast(comm, geometry.n_cells, 0);
    geometry.curved       = dealii::Utilities::MPI::broadcast(comm, geometry.curved, 0);
    return geometry;
  }

  // Errors are agreed on over a communicator of their own: a failing rank enters a
  // non-blocking barrier there and waits up to 3 s. If every rank failed (the same input read
  // everywhere: the common case) the barrier completes, rank 0 reports once and all exit. If not,
  // the others are busy (or waiting in a collective call that will never complete): this rank
  // reports itself and aborts the job, so nothing hangs.
  MPI_Comm error_communicator = MPI_COMM_NULL;

  void report_error(const std::string &message, const bool root, const int exit_code)
  {
    MPI_Request request;
    MPI_Ibarrier(error_communicator, &request);
    int        all_failed = 0;
    const auto start      = std::chrono::steady_clock::now();
    while (!all_failed && std::chrono::steady_clock::now() - start < std::chrono::seconds(3))
      {
        MPI_Test(&request, &all_failed, MPI_STATUS_IGNORE);
        if (!all_failed)
          std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
    if (all_failed)
      {
        if (root)
          std::cerr << "error: " << message << std::endl;
        return;
      }
    std::cerr << "error (rank " << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
              << " alone; the other ranks are stopped): " << message << std::endl;
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }
} // namespace

int main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm   comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  MPI_Comm_dup(comm, &error_communicator);
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
      check_output_directory(p, comm);
      const MeshedGeometry geometry = mesh_on_rank_zero(p, comm);
      // Fault injection for the rank-failure test: one rank throws, the others go on.
      if (const char *rank = std::getenv("COMPLIANT_TEST_FAIL_RANK");
          rank != nullptr && std::to_string(dealii::Utilities::MPI::this_mpi_process(comm)) == rank)
        throw std::runtime_error("failure injected on rank " + std::string(rank) +
                                 " (COMPLIANT_TEST_FAIL_RANK)");
      return find_analysis(p.analysis).run({p, prm, geometry, command_line.check, comm});
    }
  catch (const InputError &e)
    {
      report_error(e.what(), root, 2);
      return 2;
    }
  catch (const std::exception &e)
    {
      report_error(e.what(), root, 1);
      return 1;
    }
}
