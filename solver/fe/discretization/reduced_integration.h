// Discretization/Integration = reduced: the stiffness of a degree-p quadrilateral or hexahedron
// integrated with p Gauss points per direction, as CalculiX's C3D20R does, instead of p + 1. A long
// cell bending under a varying moment then carries no parasitic shear (the p-point rule does not see
// the mismatch between the element's rotation and the slope of its deflection), so it is much
// softer and nearer the answer on cells many times longer than thick. The p-point rule alone leaves
// zero-energy (hourglass) modes that spread through a mesh (measured: a clamped cantilever's tip
// moved the wrong way), so a fraction e of the fully integrated stiffness is kept:
// K = (1 - e) K_p + e K_(p+1), one quadrature rule with both point sets.
#pragma once

#include <deal.II/base/quadrature_lib.h>

#include <vector>

namespace compliant
{
  template <int dim>
  dealii::Quadrature<dim> stabilized_reduced_quadrature(const unsigned int degree, const double hourglass_stiffness)
  {
    const dealii::QGauss<dim>        reduced(degree), full(degree + 1);
    std::vector<dealii::Point<dim>> points = reduced.get_points();
    std::vector<double>             weights;
    for (const double w : reduced.get_weights())
      weights.push_back((1 - hourglass_stiffness) * w);
    for (unsigned int q = 0; q < full.size(); ++q)
      {
        points.push_back(full.point(q));
        weights.push_back(hourglass_stiffness * full.weight(q));
      }
    return dealii::Quadrature<dim>(points, weights);
  }
} // namespace compliant
