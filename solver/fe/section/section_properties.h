// Cross-section properties from the Saint-Venant warping function: area moments, the torsion
// constant, the shear centre, the warping constant and the peak torsional shear stress.
#pragma once

#include <deal.II/base/point.h>

#include "section/warping_problem.h"

namespace compliant::section
{
  struct SectionProperties
  {
    double           area = 0;
    dealii::Point<2> centroid;
    // About centroidal axes parallel to x and y: I_x = int y^2 dA (bending about x), I_y = int x^2.
    double second_moment_about_x = 0, second_moment_about_y = 0, product_moment_xy = 0;
    double polar_moment          = 0; // I_x + I_y

    // J = I_p + int (x d omega/dy - y d omega/dx) dA (Timoshenko and Goodier, sec. 104). The weak
    // form with v = omega gives the integral as -int |grad omega|^2: J <= I_p, and the FE value
    // converges to J from above (the discrete warping energy is too small).
    double torsion_constant = 0;

    // Trefftz's shear centre: omega_S = omega - y_s x + x_s y (warping about S, x, y and x_s, y_s
    // centroidal) has zero products int omega_S x dA = int omega_S y dA = 0. Coordinates here are
    // absolute (mesh coordinates).
    dealii::Point<2> shear_centre;
    // Vlasov's warping constant Gamma = int omega_S^2 dA about the shear centre, and the same
    // integral with omega about the centroid (equal for doubly symmetric sections).
    double warping_constant = 0, warping_constant_about_centroid = 0;

    // max |grad omega + (-y, x)| over the section (a length): tau_max = G theta' * max_shear_factor
    // = T * max_shear_factor / J, sampled on a lattice of points in every cell including its edges
    // and vertices (the peak is on the boundary).
    double           max_shear_factor = 0;
    dealii::Point<2> max_shear_location; // absolute
  };

  SectionProperties compute_section_properties(const WarpingProblem &problem);

  // Shear stress per unit twist rate and shear modulus at a point from the warping gradient there:
  // (tau_xz, tau_yz) / (G theta') = (d omega/dx - y, d omega/dy + x), x, y from the centroid.
  // The same for omega about any point (the shift of omega is linear and cancels).
  inline dealii::Tensor<1, 2> shear_per_unit_twist(const dealii::Tensor<1, 2> &warping_gradient,
                                                   const dealii::Point<2>     &relative_point)
  {
    dealii::Tensor<1, 2> tau = warping_gradient;
    tau[0] -= relative_point[1];
    tau[1] += relative_point[0];
    return tau;
  }
} // namespace compliant::section
