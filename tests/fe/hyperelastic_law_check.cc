// The laws for printed elastomers at one material point: S against central differences of the
// energy and dS/dE against central differences of S (2D plane strain and 3D, displacement and
// mixed), also where eigenvalues of E repeat (the Ogden tangent's divided differences take their
// limit there); Ogden with alpha = 2 and Yeoh with C20 = C30 = 0 against the neo-Hookean law
// (the same energy by other formulas); and the constants' input errors.
#include "finite_strain/hyperelastic_law.h"
#include "finite_strain/law_constants.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace compliant;
using dealii::SymmetricTensor;

namespace
{
  Material material()
  {
    Material m;
    m.name           = "test";
    m.youngs_modulus = 10;
    m.poissons_ratio = 0.45;
    return m;
  }

  const char *ogden3 = "mu1=3, alpha1=1.7, mu2=0.4, alpha2=6, mu3=0.02, alpha3=-2.5";

  // A rotated diagonal strain: principal values e (repeated ones allowed) in a general basis.
  template <int dim>
  SymmetricTensor<2, dim> strain(const double e0, const double e1, const double e2)
  {
    const double e[3] = {e0, e1, e2};
    dealii::Tensor<2, dim> Q; // rotation about z by 0.7 (and about x by 0.4 in 3D)
    const double c = std::cos(0.7), s = std::sin(0.7), c2 = std::cos(0.4), s2 = std::sin(0.4);
    Q[0][0] = c, Q[0][1] = -s, Q[1][0] = s, Q[1][1] = c;
    if (dim == 3)
      {
        dealii::Tensor<2, dim> R;
        R[0][0] = 1, R[1][1] = c2, R[1][2] = -s2, R[2][1] = s2, R[2][2] = c2;
        Q = R * Q;
      }
    dealii::Tensor<2, dim> D;
    for (unsigned int i = 0; i < dim; ++i)
      D[i][i] = e[i];
    return dealii::symmetrize(Q * D * dealii::transpose(Q));
  }

  // max |dS/dE - central differences| / |dS/dE| and |S - dW/dE| / |S| over the components
  template <int dim>
  std::pair<double, double> fd_errors(const HyperelasticLaw &law, const SymmetricTensor<2, dim> &E, bool mixed)
  {
    const double h = 1e-6, p = 0.3;
    const auto   r = law.response(E, mixed, p);
    double       tangent_error = 0, stress_error = 0;
    for (unsigned int k = 0; k < dim; ++k)
      for (unsigned int l = k; l < dim; ++l)
        {
          SymmetricTensor<2, dim> Ep = E, Em = E;
          Ep[k][l] += h, Em[k][l] -= h; // off-diagonal: moves both E_kl and E_lk
          // the stress-only response (a residual's) differentiated against the full one
          const auto rp = law.response(Ep, mixed, p, false), rm = law.response(Em, mixed, p, false);
          const double factor = k == l ? 1.0 : 0.5; // dW/dE_kl counts both off-diagonal places
          stress_error = std::max(stress_error, std::abs((rp.energy - rm.energy) / (2 * h) * factor - r.S[k][l]) /
                                                  r.S.norm());
          const SymmetricTensor<2, dim> dS = (rp.S - rm.S) / (2 * h);
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int j = i; j < dim; ++j)
              tangent_error = std::max(tangent_error, std::abs(dS[i][j] - (k == l ? 1.0 : 2.0) * r.tangent[i][j][k][l]) /
                                                        r.tangent.norm());
        }
    return {stress_error, tangent_error};
  }
} // namespace

TEST(HyperelasticLaw, ElastomerLawsMatchFiniteDifferences)
{
  const std::vector<std::pair<std::string, std::string>> laws = {
    {"Ogden", "mu1=4, alpha1=2.5"}, {"Ogden", "mu1=3, alpha1=1.7, mu2=0.4, alpha2=6"}, {"Ogden", ogden3},
    {"Yeoh", "C10=2, C20=-0.05, C30=0.01"}};
  // distinct, two repeated (one of them the plane-strain third), all repeated principal strains
  const double states[4][3] = {{0.3, -0.2, 0.15}, {0.25, 0.25, -0.1}, {0.2, -0.1, -0.1}, {0.1, 0.1, 0.1}};
  double worst = 0;
  for (const auto &[name, constants] : laws)
    for (const bool mixed : {false, true})
      for (const auto &e : states)
        {
          const HyperelasticLaw law(name, material(), 0, constants);
          const auto [s2, t2] = fd_errors<2>(law, strain<2>(e[0], e[1], 0), mixed);
          const auto [s3, t3] = fd_errors<3>(law, strain<3>(e[0], e[1], e[2]), mixed);
          // h = 1e-6: truncation h^2 ~ 1e-12 against round-off eps/h ~ 1e-10 of the scale
          worst = std::max({worst, s2, t2, s3, t3});
          EXPECT_LT(std::max({s2, t2, s3, t3}), 1e-8)
            << name << " " << constants << (mixed ? " mixed" : "") << " at " << e[0] << " " << e[1] << " " << e[2]
            << ": stress " << s2 << " " << s3 << ", tangent " << t2 << " " << t3;
        }
  std::cout << "largest difference from central differences: " << worst << std::endl;
}

TEST(HyperelasticLaw, ClosedFormLawsMatchFiniteDifferences)
{
  // The laws with a closed-form tangent, whose stress-only response (with_tangent = false, a
  // residual's) skips it: S, energy and ln J the same as the full response's to the last bit,
  // and the full tangent against differences of the stress-only S.
  const double states[3][3] = {{0.3, -0.2, 0.15}, {0.25, 0.25, -0.1}, {1e-4, -2e-4, 3e-4}};
  for (const char *name : {"neo-Hookean", "neo-Hookean isochoric", "Mooney-Rivlin", "Saint Venant-Kirchhoff"})
    for (const bool mixed : {false, true})
      for (const auto &e : states)
        {
          const HyperelasticLaw law(name, material(), 0.3);
          if (mixed && !law.supports_mixed())
            continue;
          const auto E3 = strain<3>(e[0], e[1], e[2]);
          const auto full = law.response(E3, mixed, 0.3), stress_only = law.response(E3, mixed, 0.3, false);
          EXPECT_EQ((full.S - stress_only.S).norm(), 0.) << name;
          EXPECT_EQ(full.energy, stress_only.energy) << name;
          EXPECT_EQ(full.log_J, stress_only.log_J) << name;
          const auto [s2, t2] = fd_errors<2>(law, strain<2>(e[0], e[1], 0), mixed);
          const auto [s3, t3] = fd_errors<3>(law, E3, mixed);
          // the tangent as for the elastomer laws; S against energy differences is looser at the
          // smallest state: the isochoric energy J^(-2/3) I1 - 3 cancels, leaving round-off of
          // eps 3 mu / (h |S|) ~ 1e-6 of S at strains of 1e-4
          EXPECT_LT(std::max({t2, t3}), 1e-8) << name << (mixed ? " mixed" : "") << " at " << e[0];
          EXPECT_LT(std::max({s2, s3}), 1e-6)
            << name << (mixed ? " mixed" : "") << " at " << e[0] << ": stress " << s2 << " " << s3 << ", tangent "
            << t2 << " " << t3;
        }
}

TEST(HyperelasticLaw, SpecialCasesAreNeoHookean)
{
  // Ogden alpha = 2 and Yeoh C20 = C30 = 0 are the neo-Hookean law with mu = mu1 = 2 C10
  const HyperelasticLaw neo("neo-Hookean", material(), 0, "C10=1.5, kappa=40");
  const HyperelasticLaw ogden("Ogden", material(), 0, "mu1=3, alpha1=2, kappa=40");
  const HyperelasticLaw yeoh("Yeoh", material(), 0, "C10=1.5, C20=0, C30=0, kappa=40");
  for (const auto &E : {strain<3>(0.3, -0.2, 0.15), strain<3>(1e-7, 0, -2e-7), strain<3>(0.2, 0.2, 0.2)})
    for (const HyperelasticLaw *law : {&ogden, &yeoh})
      {
        const auto a = neo.response(E, false, 0), b = law->response(E, false, 0);
        EXPECT_LT((a.S - b.S).norm(), 1e-13 * (1 + a.S.norm()));
        EXPECT_LT((a.tangent - b.tangent).norm(), 1e-13 * a.tangent.norm());
        EXPECT_NEAR(a.energy, b.energy, 1e-14 * (1 + std::abs(a.energy)));
      }
  // the small-strain limit: shear modulus sum mu_p, bulk modulus kappa (given) or from nu
  const HyperelasticLaw o3("Ogden", material(), 0, ogden3);
  const auto            t = o3.response(SymmetricTensor<2, 3>(), false, 0).tangent;
  const double          G = 3 + 0.4 + 0.02, kappa = 2 * G * 1.45 / (3 * 0.1);
  EXPECT_NEAR(t[0][1][0][1], G, 1e-12 * G);
  EXPECT_NEAR(t[0][0][1][1], kappa - 2 * G / 3, 1e-12 * kappa);
  // plane stress solves the thickness strain for these laws too: S33 = 0, uniaxial-like state
  const auto ps = o3.plane_stress_response(strain<2>(0.3, -0.1, 0));
  EXPECT_TRUE(std::isfinite(ps.S.norm()));
  EXPECT_LT(ps.E33, 0);
}

TEST(HyperelasticLaw, ConstantsInputErrors)
{
  const auto message = [](const std::string &law, const std::string &text) -> std::string {
    try
      {
        parse_law_constants(law, text);
      }
    catch (const std::invalid_argument &e)
      {
        return e.what();
      }
    return "";
  };
  const std::vector<std::tuple<std::string, std::string, std::string>> bad = {
    {"Ogden", "", "needs its constants"},
    {"Ogden", "mu1=1", "needs 'alpha1'"},
    {"Ogden", "mu1=1, alpha1=2, mu2=1, alpha2=2, mu3=1, alpha3=2, mu4=1, alpha4=2", "unexpected 'alpha4'"},
    {"Ogden", "mu1=1, alpha1=0", "alpha1 must not be 0"},
    {"Ogden", "mu1=-1, alpha1=2", "shear modulus must be > 0"},
    {"Ogden", "mu1=1, alpha1=2, mu2=-0.9, alpha2=8", "not Drucker-stable"},
    {"Yeoh", "C10=1, C20=0.1", "needs 'C30'"},
    {"Yeoh", "C10=1, C20=-2, C30=0.01", "not Drucker-stable"},
    {"Yeoh", "C10=1, C20=x, C30=0", "'C20' expects a number"},
    {"Yeoh", "C10=1, C20=0, C30=0, kappa=-3", "kappa (bulk modulus) must be > 0"},
    {"Mooney-Rivlin", "C10=1", "needs 'C01'"},
    {"Saint Venant-Kirchhoff", "C10=1", "takes nothing"}};
  for (const auto &[law, text, expected] : bad)
    {
      const std::string m = message(law, text);
      EXPECT_NE(m.find("Finite strain/Law constants"), std::string::npos) << m;
      EXPECT_NE(m.find(expected), std::string::npos) << law << " '" << text << "': " << m;
    }
  EXPECT_EQ(message("Ogden", ogden3), "");
  EXPECT_EQ(message("Mooney-Rivlin", ""), "");
}

int main(int argc, char **argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
