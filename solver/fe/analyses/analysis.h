// The kinds of analysis a case can ask for (Analysis = ...). Each one declares its own case-file
// subsection and runs from the common inputs; new analyses are added to the list in
// app/analysis_list.cc.
#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include "input/analysis_declarations.h"
#include "input/case_file.h"
#include "mesh/gmsh_geometry.h"
#include "mesh/mesh_partition.h"
#include "output/report_page.h"
#include "output/summary.h"
#include "quantities/comparison.h"

#include <functional>
#include <string>
#include <vector>

namespace compliant
{
  struct RunContext
  {
    const CaseParameters           &parameters;
    const dealii::ParameterHandler &prm;
    const MeshedGeometry           &geometry;
    bool                            check_only;
    MPI_Comm                        communicator;
  };

  // An analysis kind: what a case file may name (input/analysis_declarations.h) and how it runs.
  struct Analysis : AnalysisDeclaration
  {
    // Runs the case; returns the exit code. Throws InputError for case-file mistakes.
    std::function<int(const RunContext &)> run;
  };

  // Prints the mesh line ("Mesh: N cells, M DoFs (<description>) on R ranks"); with --check also
  // that the case is valid, and returns true: the caller stops there.
  bool report_mesh_and_stop_if_check(const RunContext &context, unsigned int n_cells,
                                     std::size_t n_dofs, const std::string &description);

  // Discretization/Mesh partition resolved for this case on this run's ranks. whole_mesh_reason
  // names what of the analysis needs the whole mesh on every rank ("" if nothing); asking for
  // 'distributed' then is an InputError.
  MeshPartitionChoice choose_mesh_partition(const RunContext &context, const CaseParameters &p,
                                            const std::string &whole_mesh_reason);
  // A summary with the settings every analysis records (analysis, model, mesh, degree, cells).
  RunSummary start_summary(const RunContext &context, bool hypercube_cells);

  // Before any work: Output/Directory must be a writable directory or creatable in one. Checked on
  // rank 0 and agreed on by every rank (an error on one rank alone would hang the others), so a
  // run that cannot write its results stops at once with a message, not after the solve.
  void check_output_directory(const CaseParameters &parameters, MPI_Comm communicator);

  // Shared end of a run: derived quantities, closed-form comparisons, fields, summary, table, and
  // with Output/Pictures the pictures draw_pictures makes from the finished summary (collective;
  // complete on rank 0) and report.html. Everything that can fail on user input happens before
  // the first file is written.
  using PictureMaker = std::function<std::vector<Picture>(const RunSummary &)>;
  void finish_run(const RunContext &context, RunSummary &summary,
                  const std::map<std::string, double>         &variables,
                  const std::function<void(const std::string &)> &write_fields,
                  const PictureMaker                             &draw_pictures = {});
} // namespace compliant
