#include "finite_strain/law_constants.h"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    const std::string where = "Finite strain/Law constants";

    std::string trim(const std::string &s)
    {
      const auto b = s.find_first_not_of(" \t");
      const auto e = s.find_last_not_of(" \t");
      return b == std::string::npos ? "" : s.substr(b, e - b + 1);
    }

    std::string expected_keys(const std::string &law)
    {
      if (law == "Ogden")
        return "mu1, alpha1 [, mu2, alpha2 [, mu3, alpha3]] (1 to 3 pairs) [, kappa]";
      if (law == "Yeoh")
        return "C10, C20, C30 [, kappa]";
      if (law == "neo-Hookean")
        return "C10 [, kappa] (or nothing: from E and nu)";
      if (law == "Mooney-Rivlin")
        return "C10, C01 [, kappa] (or nothing: from E, nu and the Mooney-Rivlin ratio)";
      return "nothing: this law takes E and nu from the material";
    }

    std::map<std::string, double> key_values(const std::string &law, const std::string &text)
    {
      std::map<std::string, double> values;
      std::stringstream             items(text);
      std::string                   item;
      while (std::getline(items, item, ','))
        {
          const auto eq = item.find('=');
          if (eq == std::string::npos)
            throw std::invalid_argument(where + ": expected 'key=value' items, got '" + trim(item) +
                                        "'; the " + law + " law takes " + expected_keys(law));
          const std::string key = trim(item.substr(0, eq)), value = trim(item.substr(eq + 1));
          std::size_t       used = 0;
          double            v    = 0;
          try
            {
              v = std::stod(value, &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          if (used == 0 || used != value.size() || !std::isfinite(v))
            throw std::invalid_argument(where + ": '" + key + "' expects a number, got '" + value + "'");
          if (!values.emplace(key, v).second)
            throw std::invalid_argument(where + ": '" + key + "' given twice");
        }
      return values;
    }

    double take(std::map<std::string, double> &values, const std::string &key, const std::string &law)
    {
      const auto it = values.find(key);
      if (it == values.end())
        throw std::invalid_argument(where + ": the " + law + " law needs '" + key + "'; expected " +
                                    expected_keys(law));
      const double v = it->second;
      values.erase(it);
      return v;
    }

    // Incompressible W as a function of the principal log strains: its first (w1) and second (w2)
    // derivatives with respect to the invariants I1 and I2 at the stretches, for the invariant laws.
    void invariant_derivatives(const std::string &law, const LawConstants &k, const double I1,
                               double &W1, double &W2, double &W11)
    {
      const double x = I1 - 3;
      W1 = k.c[0], W2 = 0, W11 = 0;
      if (law == "Mooney-Rivlin")
        W2 = k.c[1];
      if (law == "Yeoh")
        W1 += 2 * k.c[1] * x + 3 * k.c[2] * x * x, W11 = 2 * k.c[1] + 6 * k.c[2] * x;
    }

    // d2W / d eps_i d eps_j of the incompressible law at principal log strains eps.
    void hessian(const std::string &law, const LawConstants &k, const double eps[3], double H[3][3])
    {
      double l2[3], I1 = 0;
      for (int i = 0; i < 3; ++i)
        l2[i] = std::exp(2 * eps[i]), I1 += l2[i];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          H[i][j] = 0;
      if (law == "Ogden")
        {
          for (int i = 0; i < 3; ++i)
            for (std::size_t p = 0; p < k.mu.size(); ++p)
              H[i][i] += 2 * k.mu[p] * std::exp(k.alpha[p] * eps[i]);
          return;
        }
      double W1, W2, W11;
      invariant_derivatives(law, k, I1, W1, W2, W11);
      for (int i = 0; i < 3; ++i)
        {
          for (int j = 0; j < 3; ++j)
            H[i][j] = W11 * 4 * l2[i] * l2[j];
          H[i][i] += 4 * l2[i] * W1 + 4 / l2[i] * W2;
        }
    }
  } // namespace

  double LawConstants::shear_modulus(const std::string &law) const
  {
    if (law == "Ogden")
      {
        double sum = 0;
        for (const double m : mu)
          sum += m;
        return sum;
      }
    if (law == "Mooney-Rivlin")
      return 2 * (c[0] + c[1]);
    return 2 * c[0];
  }

  std::string law_constants_documentation()
  {
    return "Constants of the hyperelastic law, 'key=value, ...' in the case's stress unit (Pa in SI, "
           "MPa in mm-N-MPa), as postproc/fit_material.py writes them. Ogden: mu1, alpha1 [, mu2, "
           "alpha2 [, mu3, alpha3]] (W = sum 2 mu_p/alpha_p^2 (l1^a_p + l2^a_p + l3^a_p - 3), shear "
           "modulus sum mu_p); Yeoh: C10, C20, C30 (W = sum C_i0 (I1-3)^i, shear modulus 2 C10); "
           "neo-Hookean: C10; Mooney-Rivlin: C10, C01. Any may add kappa, the bulk modulus; without it "
           "kappa = 2 G (1+nu) / (3 (1-2 nu)) from the shear modulus G of the constants and the "
           "material's nu. Empty: neo-Hookean and Mooney-Rivlin from the material's E and nu (Ogden "
           "and Yeoh need constants). The law must be Drucker-stable in uniaxial, equibiaxial and "
           "planar stretch 0.1 to 10, else the run stops (exit 2).";
  }

  LawConstants parse_law_constants(const std::string &law, const std::string &text)
  {
    LawConstants k;
    if (trim(text).empty())
      {
        if (law == "Ogden" || law == "Yeoh")
          throw std::invalid_argument(where + ": the " + law + " law needs its constants, " +
                                      expected_keys(law) + " (postproc/fit_material.py fits them)");
        return k;
      }
    if (law != "Ogden" && law != "Yeoh" && law != "neo-Hookean" && law != "Mooney-Rivlin")
      throw std::invalid_argument(where + ": the " + law + " law takes " + expected_keys(law) +
                                  "; got '" + trim(text) + "'");
    auto values = key_values(law, text);
    k.given     = true;
    if (values.count("kappa"))
      {
        k.bulk_modulus = take(values, "kappa", law);
        if (!(k.bulk_modulus > 0))
          throw std::invalid_argument(where + ": kappa (bulk modulus) must be > 0, got " +
                                      std::to_string(k.bulk_modulus));
      }
    if (law == "Ogden")
      for (int p = 1; p <= 3 && values.count("mu" + std::to_string(p)); ++p)
        {
          k.mu.push_back(take(values, "mu" + std::to_string(p), law));
          k.alpha.push_back(take(values, "alpha" + std::to_string(p), law));
          if (k.alpha.back() == 0)
            throw std::invalid_argument(where + ": alpha" + std::to_string(p) + " must not be 0");
        }
    const std::vector<std::string> keys = law == "Yeoh" ? std::vector<std::string>{"C10", "C20", "C30"} :
                                          law == "Mooney-Rivlin" ? std::vector<std::string>{"C10", "C01"} :
                                          law == "neo-Hookean"   ? std::vector<std::string>{"C10"} :
                                                                   std::vector<std::string>{};
    for (const auto &key : keys)
      k.c.push_back(take(values, key, law));
    if (law == "Ogden" && k.mu.empty())
      take(values, "mu1", law); // throws: names the missing key
    if (!values.empty())
      throw std::invalid_argument(where + ": unexpected '" + values.begin()->first + "' for the " + law +
                                  " law; expected " + expected_keys(law));
    const double G = k.shear_modulus(law);
    if (!(G > 0))
      throw std::invalid_argument(where + ": the small-strain shear modulus must be > 0 (" +
                                  (law == "Ogden" ? "sum of mu_p" : law == "Mooney-Rivlin" ? "2 (C10 + C01)" : "2 C10") +
                                  "), got " + std::to_string(G));
    const std::string unstable = drucker_violation(law, k);
    if (!unstable.empty())
      throw std::invalid_argument(where + ": the " + law + " law with these constants is not Drucker-stable: " +
                                  unstable + " (expected stable in uniaxial, equibiaxial and planar "
                                  "stretch 0.1 to 10)");
    return k;
  }

  std::string drucker_violation(const std::string &law, const LawConstants &k)
  {
    const char *modes[] = {"uniaxial", "equibiaxial", "planar"};
    const double s6 = std::sqrt(6.0), s2 = std::sqrt(2.0);
    // a basis of the isochoric increments (trace-free principal log strains)
    const double q[2][3] = {{1 / s2, -1 / s2, 0}, {1 / s6, 1 / s6, -2 / s6}};
    for (int mode = 0; mode < 3; ++mode)
      for (int step = 0; step <= 400; ++step)
        {
          const double e = std::log(0.1) + step * (std::log(10.0) - std::log(0.1)) / 400; // ln lambda
          const double eps[3] = {e, mode == 0 ? -e / 2 : mode == 1 ? e : 0, mode == 0 ? -e / 2 : mode == 1 ? -2 * e : -e};
          double       H[3][3];
          hessian(law, k, eps, H);
          double M[2][2];
          for (int a = 0; a < 2; ++a)
            for (int b = 0; b < 2; ++b)
              {
                M[a][b] = 0;
                for (int i = 0; i < 3; ++i)
                  for (int j = 0; j < 3; ++j)
                    M[a][b] += q[a][i] * H[i][j] * q[b][j];
              }
          if (!(M[0][0] > 0 && M[0][0] * M[1][1] - M[0][1] * M[1][0] > 0))
            {
              std::ostringstream s;
              s << modes[mode] << " stretch " << std::exp(e);
              return s.str();
            }
        }
    return "";
  }
} // namespace compliant
