#include "analyses/analysis.h"
#include "output/report_files.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>


#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <iostream>

namespace compliant
{
  void check_output_directory(const CaseParameters &p, MPI_Comm communicator)
  {
    namespace fs = std::filesystem;
    std::string error;
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      {
        std::error_code ec;
        fs::path        existing = fs::absolute(p.output_directory, ec);
        if (fs::exists(existing, ec) && !fs::is_directory(existing, ec))
          error = "'" + p.output_directory + "' exists and is not a directory";
        else
          {
            while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
              existing = existing.parent_path();
            if (!fs::is_directory(existing, ec))
              error = "'" + existing.string() + "' (on the way to '" + p.output_directory +
                      "') is not a directory";
            else if (access(existing.c_str(), W_OK | X_OK) != 0)
              error = "'" + existing.string() + "' is not writable, so '" + p.output_directory +
                      "' cannot be written";
            else
              {
                // access() says yes to root everywhere (even /proc): try to create a directory.
                const fs::path probe =
                  existing / (".compliant-probe-" + std::to_string(getpid()));
                if (!fs::create_directory(probe, ec) || ec)
                  error = "no directory can be created in '" + existing.string() + "' (" +
                          ec.message() + "), so '" + p.output_directory + "' cannot be written";
                fs::remove(probe, ec);
              }
          }
      }
    error = dealii::Utilities::MPI::broadcast(communicator, error, 0);
    if (!error.empty())
      throw InputError("case file '" + p.case_file + "', Output/Directory: " + error +
                       "; give a directory you can write");
  }

  MeshPartitionChoice choose_mesh_partition(const RunContext &context, const CaseParameters &p,
                                            const std::string &whole_mesh_reason)
  {
    try
      {
        // Rank 0 decides for all: ranks that built different kinds of mesh would deadlock.
        const unsigned int n_cells = dealii::Utilities::MPI::broadcast(
          context.communicator, static_cast<unsigned int>(context.geometry.n_cells), 0);
        return choose_mesh_partition(
          p.mesh_partition,
          estimate_dofs(n_cells, p.dimension, p.global_refinements, p.element_degree),
          dealii::Utilities::MPI::n_mpi_processes(context.communicator), whole_mesh_reason);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
  }

  bool report_mesh_and_stop_if_check(const RunContext &context, const unsigned int n_cells,
                                     const std::size_t n_dofs, const std::string &description)
  {
    const auto &p    = context.parameters;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
    if (root)
      std::cout << "Mesh: " << n_cells << " cells, " << n_dofs << " DoFs (degree "
                << p.element_degree << ", " << to_string(p.model) << description << ") on "
                << dealii::Utilities::MPI::n_mpi_processes(context.communicator) << " ranks"
                << std::endl;
    if (context.check_only && root)
      std::cout << "Case '" << p.case_file << "' is valid." << std::endl;
    return context.check_only;
  }

  RunSummary start_summary(const RunContext &context, const bool hypercube_cells)
  {
    const auto &p = context.parameters;
    RunSummary  summary;
    summary.case_file  = p.case_file;
    summary.settings   = {{"analysis", p.analysis},
                        {"model", to_string(p.model)},
                        {"mesh_file", p.mesh_file},
                        {"element_degree", std::to_string(p.element_degree)},
                        {"cell_type", hypercube_cells ? "hypercube" : "simplex"},
                        {"integration", p.reduced_integration ?
                                          "reduced, hourglass stiffness " + std::to_string(p.hourglass_stiffness) :
                                          "full"}};
    summary.parameters = p.geometry_parameters;
    return summary;
  }

  void finish_run(const RunContext &context, RunSummary &summary,
                  const std::map<std::string, double>            &variables,
                  const std::function<void(const std::string &)> &write_fields,
                  const PictureMaker                             &draw_pictures)
  {
    const auto &p    = context.parameters;
    const bool  root = dealii::Utilities::MPI::this_mpi_process(context.communicator) == 0;
    {
      // Peak resident memory (VmHWM) of the largest rank: what sizes a model to a machine.
      dealii::Utilities::System::MemoryStats memory;
      dealii::Utilities::System::get_memory_stats(memory);
      // The smallest rank and the sum show how a partition spreads the model.
      const auto peak = dealii::Utilities::MPI::min_max_avg(memory.VmHWM / 1024.0, context.communicator);
      summary.quantities["memory_peak_max_rank_mb"] = peak.max;
      summary.quantities["memory_peak_min_rank_mb"] = peak.min;
      summary.quantities["memory_peak_all_ranks_mb"] = peak.sum;
    }
    try
      {
        // A nonlinear run that converged no step has no quantities to compare.
        if (summary.quantities.count("n_dofs") > 0)
          {
            if (summary.quantities.count("load_factor") == 0) // nonlinear runs added them per step
              add_derived_quantities(p.derived, summary.quantities, variables);
            summary.comparisons = run_checks(parse_checks(p.checks), summary.quantities, variables);
          }
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "': " + e.what());
      }
    if (root)
      std::filesystem::create_directories(p.output_directory);
    MPI_Barrier(context.communicator);
    if (p.write_fields && write_fields)
      write_fields(p.output_directory);
    const bool           pictures_on = p.write_pictures; // report.html too, pictures if the analysis draws
    const auto           start       = std::chrono::steady_clock::now();
    std::vector<Picture> pictures;
    if (pictures_on && draw_pictures)
      pictures = draw_pictures(summary);
    const double drawing = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (root)
      {
        write_summary(summary, p.output_directory + "/summary.json");
        if (pictures_on)
          write_pictures_and_report(p.output_directory, summary, pictures, drawing);
        std::cout << "\n"
                  << format_table(summary) << "\nResults in " << p.output_directory
                  << "/ (summary.json" << (p.write_fields ? ", fields.xdmf" : "");
        for (const auto &picture : pictures)
          std::cout << ", " << picture.file;
        if (pictures_on)
          std::cout << ", report.html; pictures and page "
                    << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s";
        std::cout << ")" << std::endl;
      }
  }
} // namespace compliant
