// The parts of Analysis = buckling shared by its two reference states: the linear static one
// (buckling.cc) and a converged finite-strain one (buckling_finite_strain.cc).
#pragma once

#include <deal.II/lac/petsc_vector.h>

#include "analyses/analysis.h"
#include "analyses/linear_static_model.h"
#include "analyses/modal_eigensolver.h"
#include "quantities/quantities.h"

#include <memory>
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

  // The Buckling subsection.
  BucklingSettings read_buckling_settings(const dealii::ParameterHandler &prm);

  // Linear buckling about the linear static state of the case's loads: the reference model (its
  // quantities, its problem) and the eigenpairs, unordered. Case-file mistakes throw InputError.
  template <int dim>
  struct LinearBuckling
  {
    LinearStaticModel<dim> model; // stopped_for_check: set up only (--check)
    EigenResult            result;
    double                 geometric_seconds = 0, eigen_seconds = 0;
  };
  template <int dim>
  LinearBuckling<dim> solve_linear_buckling(const RunContext &context, const BucklingSettings &settings);

  // Modes satisfy the supports held at zero (their constrained entries set).
  template <int dim>
  void distribute_support_constraints(const LinearElasticProblem<dim>                 &problem,
                                      std::vector<dealii::PETScWrappers::MPI::Vector> &modes);

  // buckling_factor_<n> = reference + eigenvalue, nearest the reference first (printed on root);
  // returns the eigenvectors in that order.
  std::vector<dealii::PETScWrappers::MPI::Vector> add_buckling_factors(const EigenResult &result, double reference,
                                                                       Quantities &quantities, bool root,
                                                                       double eigen_seconds);

  // Geometry/Imperfection of the case (nullptr when none, or with --check): the linear buckling
  // modes of the perfect geometry, scaled and summed; adds their buckling_factor_<n> and
  // imperfection_amplitude_<mode> to the quantities.
  template <int dim>
  std::shared_ptr<const GeometryImperfection> buckling_mode_imperfection(const RunContext &context,
                                                                         Quantities       &quantities);

  template <int dim>
  int run_buckling_about_finite_strain_state(const RunContext &context, const BucklingSettings &settings);
} // namespace compliant
