// The "Extra constraints" case-file subsection: edge supports, mirror ties and pin joints, honoured by the
// analyses that rebuild the constraints on every rank (modal, linkage). 'linear static' does not
// read it.
#pragma once

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include "discretization/discretization.h"

#include <string>

namespace compliant
{
  struct ExtraConstraints
  {
    std::string edge_supports;
    std::string mirror_ties;
    std::string pins;

    bool empty() const { return edge_supports.empty() && mirror_ties.empty() && pins.empty(); }
  };

  void             declare_extra_constraints(dealii::ParameterHandler &prm);
  ExtraConstraints read_extra_constraints(const dealii::ParameterHandler &prm);

  // Adds edge supports, then mirror ties, then pins, to constraints gathered from every rank (not closed).
  // Throws std::invalid_argument naming the entry.
  template <int dim>
  void add_extra_constraints(const Discretization<dim> &problem,
                             const ExtraConstraints          &extra,
                             dealii::AffineConstraints<double> &constraints);
} // namespace compliant
