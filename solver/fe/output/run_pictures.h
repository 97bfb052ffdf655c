// The pictures of a run (Output/Pictures): a static run's deformed part coloured by von Mises,
// with the peak of the summary (max_von_mises and where) marked; a nonlinear run's
// load-displacement chart from its curve.csv; a modal run's mode shapes, one per mode, coloured by
// the displacement magnitude. Collective (every rank samples its cells); complete on rank 0.
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "discretization/discretization.h"
#include "output/report_page.h"
#include "output/summary.h"

#include <string>
#include <vector>

namespace compliant
{
  // Problem: LinearElasticProblem<dim> or FiniteStrainProblem<dim>. curve_file: the run's
  // curve.csv ("" for a linear run).
  template <class Problem>
  std::vector<Picture> static_pictures(const Problem &problem, const RunSummary &summary,
                                       const std::string &curve_file = "");

  // modes: distributed (constraints applied), owned DoFs. At most the first 24 are drawn.
  template <int dim>
  std::vector<Picture> mode_pictures(const Discretization<dim> &discretization,
                                     const std::vector<dealii::PETScWrappers::MPI::Vector> &modes,
                                     const RunSummary &summary);
} // namespace compliant
