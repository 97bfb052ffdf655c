// The parts of Analysis = buckling shared by its two reference states: the linear static one
// (buckling.cc) and a converged finite-strain one (buckling_finite_strain.cc).
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "analyses/analysis.h"
#include "analyses/modal_eigensolver.h"
#include "quantities/quantities.h"

#include <vector>

namespace compliant
{
  struct BucklingSettings
  {
    unsigned int n_modes;
    double       tolerance;
    unsigned int max_iterations;
    double       reference_load_factor; // 0: the linear static state
  };

  // buckling_factor_<n> = reference + eigenvalue, nearest the reference first (printed on root);
  // returns the eigenvectors in that order.
  std::vector<dealii::PETScWrappers::MPI::Vector> add_buckling_factors(const EigenResult &result, double reference,
                                                                       Quantities &quantities, bool root,
                                                                       double eigen_seconds);

  template <int dim>
  int run_buckling_about_finite_strain_state(const RunContext &context, const BucklingSettings &settings);
} // namespace compliant
