// compliant: a case file in, quantities of interest, closed-form comparison, fields and a JSON
// summary out.   mpirun -np 2 compliant cases/<case>.prm [--set "Section/Name=value"] [--check]
//                [--points FILE] (many points of a study in one process, app/point_batch.h)
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <closed_forms/registry.h>

#include "analyses/analysis.h"
#include "app/analysis_list.h"
#include "app/point_batch.h"
#include "contact/contact_obstacle.h"
#include "materials/material.h"
#include "input/case_file.h"
#include "input/case_geometry.h"
#include "linear_algebra/mpi_transport.h"

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
                 "  --set     override any parameter, e.g. --set \"Geometry/Parameters/L=5\"\n"
                 "  --points FILE  run many points of a study in this one process: one line per point,\n"
                 "            its output directory, then its overrides, tab-separated; outcomes in\n"
                 "            FILE.status (postproc/study.py writes and reads these)\n\n"
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

  // True once every rank has called it (each after the same failure); if the others do not come
  // within 3 s they are busy or waiting elsewhere: false.
  bool every_rank_failed()
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
    return all_failed;
  }

  void report_error(const std::string &message, const bool root, const int exit_code)
  {
    if (every_rank_failed())
      {
        if (root)
          std::cerr << "error: " << message << std::endl;
        return;
      }
    std::cerr << "error (rank " << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
              << " alone; the other ranks are stopped): " << message << std::endl;
    MPI_Abort(MPI_COMM_WORLD, exit_code);
  }

  // A batch point failed on this rank: go on only if it failed on every rank alike.
  bool all_ranks_failed()
  {
    if (every_rank_failed())
      return true;
    std::cerr << "error (rank " << dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD)
              << " alone; the batch is stopped)" << std::endl;
    MPI_Abort(MPI_COMM_WORLD, 1);
    return false;
  }
} // namespace

namespace
{
  // One run of the case: read, mesh, analyse. Throws on any failure.
  int run_case(const CommandLine &command_line, MPI_Comm comm, const bool root)
  {
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
    if (p.analysis != "nonlinear static" && !read_contact_settings(prm).empty())
      throw InputError("case file '" + p.case_file + "', Contact/Obstacles, Contact/Pairs: contact is solved by nonlinear static "
                       "analyses, not by a " + p.analysis + " analysis");
    check_output_directory(p, comm);
    const MeshedGeometry geometry = mesh_case_geometry(p, comm);
    // Fault injection for the rank-failure test: one rank throws, the others go on.
    if (const char *rank = std::getenv("COMPLIANT_TEST_FAIL_RANK");
        rank != nullptr && std::to_string(dealii::Utilities::MPI::this_mpi_process(comm)) == rank)
      throw std::runtime_error("failure injected on rank " + std::string(rank) + " (COMPLIANT_TEST_FAIL_RANK)");
    return find_analysis(p.analysis).run({p, prm, geometry, command_line.check, comm});
  }

  // "--points FILE" taken out of the arguments (the rest are the case's).
  std::string take_points_option(int &argc, char **argv)
  {
    std::string file;
    int         kept = 1;
    for (int i = 1; i < argc; ++i)
      if (std::string(argv[i]) == "--points")
        {
          if (i + 1 >= argc)
            throw InputError("--points needs a file (one point per line: output directory, then "
                             "\"Section/Name=value\" overrides, tab-separated)");
          file = argv[++i];
        }
      else
        argv[kept++] = argv[i];
    argc = kept;
    return file;
  }
} // namespace

int main(int argc, char **argv)
{
  prefer_shared_memory_transport(); // before MPI_Init: 0.2 s of every start (linear_algebra/mpi_transport.h)
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MPI_Comm   comm = MPI_COMM_WORLD;
  const bool root = dealii::Utilities::MPI::this_mpi_process(comm) == 0;
  MPI_Comm_dup(comm, &error_communicator);
  try
    {
      register_analyses();
      const std::string points_file  = take_points_option(argc, argv);
      const CommandLine command_line = parse_command_line(argc, argv);
      if (points_file.empty())
        return run_case(command_line, comm, root);
      std::vector<BatchPoint> points;
      try
        {
          points = read_batch_points(points_file);
        }
      catch (const std::runtime_error &e)
        {
          throw InputError(e.what()); // bad input: exit 2
        }
      const auto run_point = [&](const BatchPoint &point) {
        CommandLine at_point = command_line;
        at_point.overrides.insert(at_point.overrides.end(), point.overrides.begin(), point.overrides.end());
        at_point.overrides.push_back("Output/Directory=" + point.output_directory);
        const int code = run_case(at_point, comm, root);
        if (code != 0)
          throw std::runtime_error("exit code " + std::to_string(code));
      };
      return run_batch(points_file, points, run_point, [] { return all_ranks_failed(); }, comm);
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
