// Hyperelastic laws for total-Lagrangian finite strain, in terms of the right Cauchy-Green
// tensor C = I + 2E: second Piola-Kirchhoff stress S = 2 dW/dC and material tangent CC = 4 d2W/dC2.
// In 2D the model is plane strain (C33 = 1) or, through plane_stress_response, plane stress
// (C33 solved locally so that S33 = 0, tangent condensed).
//
// Mooney-Rivlin family (compressible; Holzapfel, Nonlinear Solid Mechanics, 2000, sec. 6.5):
//   W = c1 (I1 - 3) + c2 (I2 - 3) - 2 (c1 + 2 c2) ln J + lambda/2 (ln J)^2
// with mu = 2 (c1 + c2) and lambda chosen so that the small-strain limit has the Lame constants
// of (E, nu); c2 = 0 is the compressible neo-Hookean law. For the mixed u-p formulation the
// volumetric term lambda/2 (ln J)^2 is replaced by p ln J - p^2/(2 lambda).
// Saint Venant-Kirchhoff: W = lambda/2 (tr E)^2 + mu E:E.
// Neo-Hookean with isochoric split (the deal.II code gallery's compressible Cook's membrane):
//   W = mu/2 (J^(-2/3) I1 - 3) + kappa/4 (J^2 - 1 - 2 ln J), kappa = lambda + 2 mu/3.
// Printed elastomers (constants from 'Finite strain/Law constants', law_constants.h), in the same
// compressible form as the Mooney-Rivlin family (not split; the ln J term makes S = 0 at C = I):
//   Ogden: W = sum_p 2 mu_p/alpha_p^2 (tr C^(alpha_p/2) - 3) - (sum_p 2 mu_p/alpha_p) ln J + V(J)
//   Yeoh:  W = sum_i C_i0 (I1 - 3)^i - 2 C10 ln J + V(J)
// with V = lambda/2 (ln J)^2 (or p ln J - p^2/(2 lambda), mixed). Small strain: shear modulus
// sum mu_p (Ogden), 2 C10 (Yeoh); lambda = kappa - 2 mu/3 with the bulk modulus kappa given or from
// the material's nu. Incompressible, they are the laws fit_material fits (Ogden's mu_p, alpha_p as
// in Ogden 1972 / Abaqus). tr C^(a) comes from the eigenvalues of E, its derivative from the
// divided differences of the power function (Daleckii-Krein), stable at repeated eigenvalues.
#pragma once

#include <deal.II/base/symmetric_tensor.h>

#include "finite_strain/law_constants.h"
#include "materials/material.h"

#include <string>
#include <vector>

namespace compliant
{
  template <int dim>
  struct StressResponse
  {
    dealii::SymmetricTensor<2, dim> S;       // second Piola-Kirchhoff
    dealii::SymmetricTensor<4, dim> tangent; // dS/dE
    double                          energy   = 0;
    double                          S33      = 0; // out-of-plane S in plane strain
    double                          E33      = 0; // out-of-plane strain in plane stress
    dealii::SymmetricTensor<2, dim> dE33_dE;      // its derivative (plane stress): dE33 = dE33_dE : dE
    double                          log_J    = 0;
  };

  // The laws offered by 'Finite strain/Law', in the order --help lists them: the selection and
  // its documentation are made from this list, so a new law is added here (its name and formula)
  // and as a branch of HyperelasticLaw, in this folder only.
  struct HyperelasticLawEntry
  {
    const char *name;
    const char *formula; // "" when the name says it
  };
  const std::vector<HyperelasticLawEntry> &hyperelastic_laws();
  std::string hyperelastic_law_selection();     // "neo-Hookean|...", a Patterns::Selection
  std::string hyperelastic_law_documentation(); // the entry's --help text

  class HyperelasticLaw
  {
  public:
    // kind: a name of hyperelastic_laws() (else std::invalid_argument); mooney_rivlin_ratio =
    // c2 / (c1 + c2) in [0, 1). constants: 'Finite strain/Law constants' (law_constants.h), in the
    // case's stress unit; empty: from the material's E and nu (not for Ogden and Yeoh).
    HyperelasticLaw(const std::string &kind, const Material &material, double mooney_rivlin_ratio,
                    const std::string &constants = "");

    // Full response to the Green-Lagrange strain E = (C - I)/2 (E, not C: the stress of small
    // strains is then free of cancellation); with `mixed`, the volumetric part is carried by the
    // pressure p instead. Without `with_tangent` (a residual) the neo-Hookean, Mooney-Rivlin,
    // Saint Venant-Kirchhoff and isochoric laws leave `tangent` zero: it costs more than S.
    template <int dim>
    StressResponse<dim> response(const dealii::SymmetricTensor<2, dim> &E, bool mixed,
                                 double pressure, bool with_tangent = true) const;

    // Plane stress: the 3D law with the thickness strain E33 solved from S33 = 0 (Newton on one
    // scalar per point), the in-plane tangent condensed, dS/dE = T - T_ab33 T_33cd / T_3333.
    // If no thickness strain balances S33 (a point crushed beyond the law), S is NaN.
    StressResponse<2> plane_stress_response(const dealii::SymmetricTensor<2, 2> &E) const;

    double lambda() const { return lambda_volumetric; }
    bool   is_saint_venant_kirchhoff() const { return svk; }
    bool   supports_mixed() const { return !svk && !isochoric; }

    double small_strain_shear_modulus() const { return mu; }

  private:
    template <int dim>
    StressResponse<dim> ogden_response(const dealii::SymmetricTensor<2, dim> &E, bool mixed,
                                       double pressure) const; // hyperelastic_law_elastomers.cc
    template <int dim>
    StressResponse<dim> yeoh_response(const dealii::SymmetricTensor<2, dim> &E, bool mixed,
                                      double pressure) const; // hyperelastic_law_elastomers.cc

    bool         svk, isochoric, ogden, yeoh;
    double       c1, c2, lambda_volumetric, mu, lambda_small_strain;
    LawConstants constants; // Ogden's mu_p, alpha_p or Yeoh's C_i0 (law_constants.h)
  };
  // E = (H + H^T + H^T H) / 2 from the displacement gradient H, without forming C - I.
  template <int dim>
  dealii::SymmetricTensor<2, dim> green_lagrange(const dealii::Tensor<2, dim> &H)
  {
    return dealii::symmetrize(H) + 0.5 * dealii::symmetrize(dealii::transpose(H) * H);
  }
} // namespace compliant
