// Adaptive refinement for the model ladder: indicators on the solved linear model mark the cells
// with the largest ones, and the marks are returned as refine flags that create_triangulation
// replays (CaseParameters::adaptive_refinements) so that every later model, linear or finite
// strain, is built on the same adapted mesh with hanging-node constraints.
//
// Goal-oriented (dual-weighted) indicators where the target quantities have a dual: the error of
// a goal J is a(e, e*) with e* the dual's error, bounded cell by cell by ||e||_K ||e*||_K
// (Prudhomme and Oden), so a cell's indicator is Kelly's for the primal solution times Kelly's
// for the dual solution z (K z = j, one more solve with the primal's operator and solver). One
// dual per target, relative to its value: a derived target's parts combined by its linearization
// (finite differences of its expression), signed, so that errors that cancel in the target cancel
// in its dual. Reactions, moments and stiffnesses have duals through their boundary's lifting
// (quantities/goal_functionals.h); the strain energy is energy-like: Kelly's indicator squared
// over the energy.
#pragma once

#include "elasticity/linear_elastic_problem.h"
#include "finite_strain/finite_strain_problem.h"
#include "quantities/quantities.h"

#include <string>
#include <vector>

namespace compliant
{
  // Refine flags (as Triangulation::save_refine_flags writes them, the same on every rank) marking the cells whose Kelly
  // indicators make up the given fraction of cells, largest first; the level difference across
  // faces stays at most one (prepare_coarsening_and_refinement).
  template <int dim>
  std::vector<bool> kelly_refine_flags(Discretization<dim> &problem, const dealii::PETScWrappers::MPI::Vector &solution,
                                       double cell_fraction);

  // The same with dual-weighted indicators for the targets (quantity names; values: the model's
  // quantities, derived ones included; derived: Quantities/Derived). how: which indicator each
  // target got, for the log.
  template <int dim>
  std::vector<bool> goal_oriented_refine_flags(LinearElasticProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, double cell_fraction, std::string &how);

  // The same for a finite-strain problem at its converged state: a target's dual solves
  // K_T z = j with the tangent at that state, j the target's derivative there (point
  // displacements and boundary rotations: as in linear elasticity; reactions, moments and
  // stiffnesses: j = K_T psi), its functionals from a linear model of the same case and mesh.
  // Stresses at points and the strain energy count as energy-like.
  // Beyond this many DoFs a 3D tangent that Newton solved matrix-free is not factored for a dual
  // (Kelly's indicator then, and the log says so).
  inline constexpr unsigned int max_factored_dual_dofs = 300000;
  template <int dim>
  std::vector<bool> finite_strain_refine_flags(FiniteStrainProblem<dim> &problem,
                                               const std::vector<std::string> &targets, const Quantities &values,
                                               const std::string &derived, double cell_fraction, std::string &how);
} // namespace compliant
