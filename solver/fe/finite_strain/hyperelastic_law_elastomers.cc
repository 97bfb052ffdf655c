// The laws for printed elastomers, Ogden and Yeoh (formulas in hyperelastic_law.h).
#include "finite_strain/hyperelastic_law.h"

#include "finite_strain/hyperelastic_law_tools.h"

#include <cmath>

namespace compliant
{
  using namespace dealii;

  namespace
  {
    // (lambda_i^m - lambda_j^m) / (lambda_i - lambda_j) with lambda = exp(L), and its limit
    // m lambda^(m-1) for equal stretches, without cancellation near them.
    double power_divided_difference(const double m, const double Li, const double Lj)
    {
      const double d = Li - Lj;
      if (std::abs(d) < 1e-7) // the limit at the midpoint: error O(d^2)
        return m * std::exp((m - 1) * 0.5 * (Li + Lj));
      return std::exp((m - 1) * Lj) * std::expm1(m * d) / std::expm1(d);
    }
  } // namespace

  template <int dim>
  StressResponse<dim> HyperelasticLaw::ogden_response(const SymmetricTensor<2, dim> &E, const bool mixed,
                                                      const double pressure) const
  {
    StressResponse<dim> r;
    // principal directions of E are those of C; L_i = ln lambda_i^2 = ln(1 + 2 e_i)
    const auto eigen = eigenvectors(E, SymmetricTensorEigenvectorMethod::jacobi);
    double     L[dim];
    double     sum_L = 0;
    for (unsigned int i = 0; i < dim; ++i)
      L[i] = std::log1p(2 * eigen[i].first), sum_L += L[i];
    r.log_J = 0.5 * sum_L; // plane strain: L_3 = 0
    double a = 0;          // the ln J coefficient, sum 2 mu_p / alpha_p
    for (std::size_t p = 0; p < constants.mu.size(); ++p)
      a += 2 * constants.mu[p] / constants.alpha[p];
    const double pr = mixed ? pressure : lambda_volumetric * r.log_J;

    // S = sum_p 2 mu_p/alpha_p (C^(alpha_p/2 - 1) - C^-1) + p C^-1, principal values by expm1
    double s[dim];
    r.energy = -a * r.log_J + (mixed ? pressure * r.log_J - pressure * pressure / (2 * lambda_volumetric) :
                                       0.5 * lambda_volumetric * r.log_J * r.log_J);
    for (unsigned int i = 0; i < dim; ++i)
      {
        s[i] = pr * std::exp(-L[i]);
        for (std::size_t p = 0; p < constants.mu.size(); ++p)
          {
            const double mu_p = constants.mu[p], alpha_p = constants.alpha[p];
            s[i] += 2 * mu_p / alpha_p * (std::expm1((alpha_p / 2 - 1) * L[i]) - std::expm1(-L[i]));
            r.energy += 2 * mu_p / (alpha_p * alpha_p) * std::expm1(alpha_p / 2 * L[i]);
          }
      }
    // dS/dE = 2 dS/dC = sum_ij theta_ij (n_i n_j) (x) sym(n_i n_j): theta holds the divided
    // differences of the principal functions (Daleckii-Krein); C^-1's are -1/(lambda_i lambda_j).
    double theta[dim][dim];
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          theta[i][j] = 2 * (a - pr) * std::exp(-L[i] - L[j]);
          for (std::size_t p = 0; p < constants.mu.size(); ++p)
            theta[i][j] += 4 * constants.mu[p] / constants.alpha[p] *
                           power_divided_difference(constants.alpha[p] / 2 - 1, L[i], L[j]);
        }
    for (unsigned int i = 0; i < dim; ++i)
      r.S += s[i] * symmetrize(outer_product(eigen[i].second, eigen[i].second));
    for (unsigned int a1 = 0; a1 < dim; ++a1)
      for (unsigned int b1 = a1; b1 < dim; ++b1)
        for (unsigned int c1 = 0; c1 < dim; ++c1)
          for (unsigned int d1 = c1; d1 < dim; ++d1)
            {
              double value = 0;
              for (unsigned int i = 0; i < dim; ++i)
                for (unsigned int j = 0; j < dim; ++j)
                  {
                    const Tensor<1, dim> &ni = eigen[i].second, &nj = eigen[j].second;
                    value += theta[i][j] * ni[a1] * nj[b1] * 0.5 * (ni[c1] * nj[d1] + ni[d1] * nj[c1]);
                  }
              r.tangent[a1][b1][c1][d1] = value;
            }
    if (!mixed)
      {
        SymmetricTensor<2, dim> Ci;
        for (unsigned int i = 0; i < dim; ++i)
          Ci += std::exp(-L[i]) * symmetrize(outer_product(eigen[i].second, eigen[i].second));
        r.tangent += lambda_volumetric * outer_product(Ci, Ci);
      }
    if (dim == 2)
      r.S33 = pr; // the Ogden terms vanish at lambda_3 = 1
    return r;
  }

  template <int dim>
  StressResponse<dim> HyperelasticLaw::yeoh_response(const SymmetricTensor<2, dim> &E, const bool mixed,
                                                     const double pressure) const
  {
    StressResponse<dim>           r;
    const SymmetricTensor<2, dim> I = unit_symmetric_tensor<dim>();
    r.log_J                         = law_tools::log_J(E);
    const SymmetricTensor<2, dim> C  = I + 2 * E;
    const auto                    Ci = invert(C);
    const auto                    IC = law_tools::inverse_product(Ci);
    const double C10 = constants.c[0], C20 = constants.c[1], C30 = constants.c[2];
    const double x   = 2 * trace(E); // I1 - 3 (also in plane strain: C33 = 1)
    // dW/dI1 - C10 and d2W/dI1^2
    const double W1_minus_C10 = x * (2 * C20 + 3 * C30 * x), W11 = 2 * C20 + 6 * C30 * x;
    const double a  = 2 * C10;
    const double pr = mixed ? pressure : lambda_volumetric * r.log_J;
    // I - C^-1 = 2 C^-1 E, free of cancellation at small strain
    const SymmetricTensor<2, dim> I_minus_Ci = symmetrize(2 * (Tensor<2, dim>(Ci) * Tensor<2, dim>(E)));
    r.S       = a * I_minus_Ci + 2 * W1_minus_C10 * I + pr * Ci;
    r.tangent = 4 * W11 * outer_product(I, I) + 2 * (a - pr) * IC;
    if (!mixed)
      r.tangent += lambda_volumetric * outer_product(Ci, Ci);
    r.energy = x * (C10 + x * (C20 + x * C30)) - a * r.log_J +
               (mixed ? pressure * r.log_J - pressure * pressure / (2 * lambda_volumetric) :
                        0.5 * lambda_volumetric * r.log_J * r.log_J);
    if (dim == 2)
      r.S33 = 2 * W1_minus_C10 + pr;
    return r;
  }

  template StressResponse<2> HyperelasticLaw::ogden_response<2>(const SymmetricTensor<2, 2> &, bool, double) const;
  template StressResponse<3> HyperelasticLaw::ogden_response<3>(const SymmetricTensor<2, 3> &, bool, double) const;
  template StressResponse<2> HyperelasticLaw::yeoh_response<2>(const SymmetricTensor<2, 2> &, bool, double) const;
  template StressResponse<3> HyperelasticLaw::yeoh_response<3>(const SymmetricTensor<2, 3> &, bool, double) const;
} // namespace compliant
