#include "finite_strain/hyperelastic_law.h"

#include "finite_strain/hyperelastic_law_tools.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace compliant
{
  using namespace dealii;
  using law_tools::inverse_product, law_tools::log_J;

  const std::vector<HyperelasticLawEntry> &hyperelastic_laws()
  {
    static const std::vector<HyperelasticLawEntry> laws = {
      {"neo-Hookean", "W = mu/2 (I1-3) - mu ln J + lambda/2 (ln J)^2"},
      {"neo-Hookean isochoric", "W = mu/2 (J^(-2/3) I1 - 3) + kappa/4 (J^2 - 1 - 2 ln J) (deal.II code gallery)"},
      {"Mooney-Rivlin", "W = c1 (I1-3) + c2 (I2-3) - 2(c1+2c2) ln J + lambda/2 (ln J)^2"},
      {"Saint Venant-Kirchhoff", "W = lambda/2 (tr E)^2 + mu E:E"},
      {"Ogden", "W = sum_p 2 mu_p/alpha_p^2 (tr C^(alpha_p/2) - 3) - (sum_p 2 mu_p/alpha_p) ln J + lambda/2 (ln J)^2, "
                "1 to 3 terms (constants from Law constants)"},
      {"Yeoh", "W = C10 (I1-3) + C20 (I1-3)^2 + C30 (I1-3)^3 - 2 C10 ln J + lambda/2 (ln J)^2 (constants from Law "
               "constants)"}};
    return laws;
  }

  std::string hyperelastic_law_selection()
  {
    std::string names;
    for (const auto &law : hyperelastic_laws())
      names += (names.empty() ? "" : "|") + std::string(law.name);
    return names;
  }

  std::string hyperelastic_law_documentation()
  {
    std::string text = "Hyperelastic law (compressible; small-strain limit has the material's E and nu unless "
                       "Law constants gives the law's own; lambda = kappa - 2 mu/3).";
    for (const auto &law : hyperelastic_laws())
      if (law.formula[0] != '\0')
        text += " " + std::string(law.name) + ": " + law.formula + ".";
    return text;
  }

  HyperelasticLaw::HyperelasticLaw(const std::string &kind, const Material &material,
                                   const double mooney_rivlin_ratio, const std::string &constants_text)
    : svk(kind == "Saint Venant-Kirchhoff")
    , isochoric(kind == "neo-Hookean isochoric")
    , ogden(kind == "Ogden")
    , yeoh(kind == "Yeoh")
  {
    bool known = false;
    for (const auto &law : hyperelastic_laws())
      known = known || kind == law.name;
    if (!known)
      throw std::invalid_argument("Finite strain/Law: unknown law '" + kind + "'; expected one of " +
                                  hyperelastic_law_selection());
    constants           = parse_law_constants(kind, constants_text);
    mu                  = material.shear_modulus();
    lambda_small_strain = material.lame_lambda();
    const double ratio  = kind == "Mooney-Rivlin" ? mooney_rivlin_ratio : 0.0;
    c1                  = (1 - ratio) * mu / 2;
    c2                  = ratio * mu / 2;
    if (constants.given)
      {
        // the law's own shear modulus; the bulk modulus given, or from the material's nu
        mu = constants.shear_modulus(kind);
        const double nu = material.poissons_ratio;
        const double kappa =
          constants.bulk_modulus > 0 ? constants.bulk_modulus : 2 * mu * (1 + nu) / (3 * (1 - 2 * nu));
        lambda_small_strain = kappa - 2 * mu / 3;
        c1 = kind == "neo-Hookean" || kind == "Mooney-Rivlin" ? constants.c[0] : mu / 2;
        c2 = kind == "Mooney-Rivlin" ? constants.c[1] : 0.0;
      }
    // the c2 term adds 4 c2 to the small-strain lambda: compensate so E and nu hold at C = I
    lambda_volumetric = lambda_small_strain - 4 * c2;
  }

  template <int dim>
  StressResponse<dim> HyperelasticLaw::response(const SymmetricTensor<2, dim> &E, const bool mixed,
                                                const double pressure, const bool with_tangent) const
  {
    StressResponse<dim>           r;
    if (ogden)
      return ogden_response(E, mixed, pressure);
    if (yeoh)
      return yeoh_response(E, mixed, pressure);
    const SymmetricTensor<2, dim> I   = unit_symmetric_tensor<dim>();
    const double                  trE = trace(E);
    r.log_J                           = log_J(E);
    if (svk)
      {
        r.S       = lambda_small_strain * trE * I + 2 * mu * E;
        if (with_tangent)
          r.tangent = lambda_small_strain * outer_product(I, I) + 2 * mu * identity_tensor<dim>();
        r.energy  = 0.5 * lambda_small_strain * trE * trE + mu * (E * E);
        r.S33     = dim == 2 ? lambda_small_strain * trE : 0;
        return r;
      }
    const SymmetricTensor<2, dim> C   = I + 2 * E;
    const auto                    Ci  = invert(C);
    if (isochoric)
      {
        const double kappa = lambda_small_strain + 2 * mu / 3;
        const double I1    = trace(C) + (dim == 2 ? 1.0 : 0.0); // C33 = 1 in plane strain
        const double Jm23  = std::exp(-2.0 / 3.0 * r.log_J);
        const double J2m1  = std::expm1(2 * r.log_J); // J^2 - 1 without cancellation
        r.S = mu * Jm23 * (I - I1 / 3 * Ci) + 0.5 * kappa * J2m1 * Ci;
        if (with_tangent)
          {
            const auto IC = inverse_product(Ci);
            r.tangent     = 2 * mu * Jm23 *
                          (-1.0 / 3 * outer_product(I, Ci) - 1.0 / 3 * outer_product(Ci, I) +
                           I1 / 9 * outer_product(Ci, Ci) + I1 / 3 * IC) +
                        kappa * (J2m1 + 1) * outer_product(Ci, Ci) - kappa * J2m1 * IC;
          }
        r.energy = 0.5 * mu * (Jm23 * I1 - 3) + 0.25 * kappa * (J2m1 - 2 * r.log_J);
        if (dim == 2)
          r.S33 = mu * Jm23 * (1 - I1 / 3) + 0.5 * kappa * J2m1;
        return r;
      }
    const double                  a   = 2 * (c1 + 2 * c2);
    // I - C^-1 = 2 C^-1 E, symmetric in exact arithmetic
    const SymmetricTensor<2, dim> I_minus_Ci = symmetrize(2 * (Tensor<2, dim>(Ci) * Tensor<2, dim>(E)));
    // p plays the role of lambda ln J in the mixed form
    const double p = mixed ? pressure : lambda_volumetric * r.log_J;

    // 2 c1 (I - C^-1) + 2 c2 [(I1 I - C) - 2 C^-1] + p C^-1, the bracket = 2 tr E I - 2 E + 2 (I - C^-1)
    r.S = 2 * c1 * I_minus_Ci + 2 * c2 * (2 * trE * I - 2 * E + 2 * I_minus_Ci) + p * Ci;
    if (with_tangent)
      {
        r.tangent = 4 * c2 * (outer_product(I, I) - identity_tensor<dim>()) + 2 * (a - p) * inverse_product(Ci);
        if (!mixed)
          r.tangent += lambda_volumetric * outer_product(Ci, Ci);
      }
    // I1 - 3 = 2 tr E; I2 - 3 = 4 tr E + 2 ((tr E)^2 - E:E) (also in plane strain, C33 = 1)
    r.energy = c1 * 2 * trE + c2 * (4 * trE + 2 * (trE * trE - E * E)) - a * r.log_J +
               (mixed ? pressure * r.log_J - pressure * pressure / (2 * lambda_volumetric) :
                        0.5 * lambda_volumetric * r.log_J * r.log_J);
    // S33 = 2 c1 + 2 c2 (I1 - 1) - a + p with I1 - 1 = 2 + 2 tr E
    if (dim == 2)
      r.S33 = 4 * c2 * trE + p;
    return r;
  }

  StressResponse<2> HyperelasticLaw::plane_stress_response(const SymmetricTensor<2, 2> &E) const
  {
    // small-strain plane stress as the start: E33 = -nu/(1-nu) (E11 + E22) = -lambda/(lambda+2mu) tr E
    double E33 = -lambda_small_strain / (lambda_small_strain + 2 * mu) * trace(E);
    SymmetricTensor<2, 3> E3;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = a; b < 2; ++b)
        E3[a][b] = E[a][b];
    // S33 rises monotonically with E33 for these laws: Newton, kept inside a bracket [lower, upper]
    // that shrinks with every evaluation and falls back to bisection, so it cannot diverge.
    double            lower = -0.5, upper = std::numeric_limits<double>::infinity();
    StressResponse<3> r3;
    bool              converged = false;
    for (unsigned int iteration = 0; iteration < 200; ++iteration)
      {
        E3[2][2] = E33;
        r3       = response<3>(E3, false, 0.0);
        const double residual = r3.S[2][2];
        if (std::abs(residual) <= 1e-13 * (mu + r3.S.norm()))
          {
            converged = true;
            break;
          }
        (residual > 0 ? upper : lower) = E33;
        const double slope = r3.tangent[2][2][2][2];
        double       next  = E33 - residual / slope;
        if (!(slope > 0) || !(next > lower && next < upper))
          next = std::isfinite(upper) ? 0.5 * (lower + upper) : E33 + std::max(1.0, std::abs(E33));
        if (next == E33)
          {
            converged = true; // the bracket has shrunk to round-off
            break;
          }
        E33 = next;
      }
    if (!converged || !std::isfinite(r3.S.norm()))
      {
        // The caller decides: assembly treats it like an inverted element (the step is cut back).
        StressResponse<2> failed;
        failed.S      = std::numeric_limits<double>::quiet_NaN() * unit_symmetric_tensor<2>();
        failed.energy = std::numeric_limits<double>::quiet_NaN();
        return failed;
      }
    StressResponse<2> r;
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = a; b < 2; ++b)
        {
          r.S[a][b] = r3.S[a][b];
          for (unsigned int c = 0; c < 2; ++c)
            for (unsigned int d = c; d < 2; ++d)
              r.tangent[a][b][c][d] = r3.tangent[a][b][c][d] - r3.tangent[a][b][2][2] *
                                                                  r3.tangent[2][2][c][d] /
                                                                  r3.tangent[2][2][2][2];
        }
    // S33(E, E33) = 0 holds along the solution: dE33 = -(C_33ab dE_ab) / C_3333.
    for (unsigned int a = 0; a < 2; ++a)
      for (unsigned int b = a; b < 2; ++b)
        r.dE33_dE[a][b] = -r3.tangent[2][2][a][b] / r3.tangent[2][2][2][2];
    r.energy = r3.energy;
    r.log_J  = r3.log_J;
    r.E33    = E33;
    return r;
  }

  template StressResponse<2> HyperelasticLaw::response<2>(const SymmetricTensor<2, 2> &, bool,
                                                          double, bool) const;
  template StressResponse<3> HyperelasticLaw::response<3>(const SymmetricTensor<2, 3> &, bool,
                                                          double, bool) const;
} // namespace compliant
