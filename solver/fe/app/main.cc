// compliant: a case file in, quantities of interest, closed-form comparison, fields and a JSON
// summary out.   mpirun -np 2 compliant cases/<case>.prm [--set "Section/Name=value"] [--check]
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <closed_forms/registry.h>

#include "analyses/analysis.h"
#include "app/analysis_list.h"
#include "materials/material.h"
#include "input/case_file.h"
#include "input/case_geometry.h"

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
      register_analyses();
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
      const MeshedGeometry geometry = mesh_case_geometry(p, comm);
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
