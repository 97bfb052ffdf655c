// Quantities/Error estimates = true: each quantity of a linear static run with an estimate of its
// discretization error, by the dual-weighted residual (DWR) with the dual at degree p + 1.
//
// For a quantity J linear in u (a displacement or rotation at a point, a mean displacement, a
// reaction force or moment, a stress at a point of the recovered field) the DWR estimate of
// J(u) - J(u_p) with the dual z solved on the degree-(p+1) space V+ of the same mesh,
// a(v, z) = J(v) for all v in V+, is R(z) = l(z) - a(u_p, z) = a(u+ - u_p, z) = J(u+) - J(u_p),
// u+ the degree-(p+1) solution. One enriched solve therefore gives every quantity's estimate at
// once, however many the case names, instead of one dual solve each. For the strain energy (a
// quadratic functional) the same difference is its DWR estimate to leading order; for a peak (max
// von Mises) it says how far the value still moves. The estimate is trustworthy where u+ is
// markedly closer to u than u_p (smooth solutions, and singular ones once the mesh is graded); at an
// unresolved singularity both converge alike and the estimate falls short. Triangles and
// tetrahedra stop at degree 2: there the dual lives on the once-refined mesh at the same degree
// (the identity holds for any V+ containing V_p), and the estimate is short by the factor
// 1 - 2^-r of the rate r (0.75 to 0.9), which is not corrected for: no order is assumed.
#pragma once

#include "analyses/linear_static_model.h"
#include "output/summary.h"

#include <functional>
#include <map>
#include <string>

namespace compliant
{
  struct QuantityEstimates
  {
    std::map<std::string, double> absolute; // |J(u+) - J(u_p)|
    std::map<std::string, double> relative; // absolute / |J(u_p)|; none for a round-off component
    std::string                   how;   // the enriched space, or why there is none
    bool                          available = false;
    unsigned int                  dual_degree = 0;
    std::size_t                   dual_dofs   = 0;
    double                        dual_seconds = 0; // the enriched model: set-up, assembly, solve
    double                        dual_solve_seconds = 0; // its linear solve alone
    unsigned int                  dual_iterations    = 0;
    bool                          warm_started       = false; // from the degree-p solution
  };

  // Quantities that are results of the model (not counts, times, iterations, nor where a peak is).
  bool has_error_estimate(const std::string &name);

  // Solves the enriched model of a case (its parameters given) and returns its quantities and DoFs.
  using EnrichedSolve = std::function<std::pair<Quantities, std::size_t>(const RunContext &, const CaseParameters &)>;

  // The enriched model of the case (same mesh, degree p + 1) solved by `solve`, and the estimates
  // of every quantity of `values` that has one (values may include derived quantities: they are
  // derived from the enriched model's quantities alike). hypercube_cells: the mesh's cells are
  // quadrilaterals or hexahedra (degrees to 4), else simplices (to 2). Without `solve`: the linear
  // static model. Modal runs pass theirs: an eigenvalue's dual is its own mode, and the DWR estimate
  // of omega^2 is omega+^2 - omega_p^2 to leading order (Heuveline and Rannacher).
  //
  // primal (the linear static model's problem, solved): the enriched solve starts from its
  // solution carried to degree p + 1 and stops once the residual has dropped by
  // enriched_solve_reduction, where the matrix-free solver is used; otherwise from zero.
  template <int dim>
  QuantityEstimates estimate_quantity_errors(const RunContext &context, const CaseParameters &parameters,
                                             const Quantities &values, bool hypercube_cells,
                                             const EnrichedSolve &solve = {},
                                             const LinearElasticProblem<dim> *primal = nullptr);

  // The enriched solve's residual reduction from the warm start (cases/verification/
  // error_estimates.md; 2D and 3D, Q1 and Q2, against the solve from zero to 1e-10): 1e-2 and 1e-3
  // (2 iterations) moved the estimates of stresses, displacements, moments and energies by < 1.5 %,
  // but a reaction that balances the load exactly (true error round-off) got an estimate of ~1e-7
  // of itself; 1e-4 (3 iterations) moves the estimates by < 3.3 % (< 1.2 % but for one) and leaves
  // such reactions below 1e-7; 1e-5 (4 iterations) costs a third more in 3D.
  inline constexpr double enriched_solve_reduction = 1e-4;

  // The enriched model's 'Mesh partition': the model's own, or its state (solution, degree-1
  // level, finite-strain state) cannot be carried over; auto would distribute the 4-8 times larger
  // enriched model alone.
  inline PartitionRequest partition_of_model(const MeshPartition partition)
  {
    return partition == MeshPartition::distributed ? PartitionRequest::distributed : PartitionRequest::shared;
  }

  // <name>_error_estimate (relative) and <name>_error_estimate_absolute for each, and how.
  void add_error_estimates(RunSummary &summary, const QuantityEstimates &estimates);
} // namespace compliant
