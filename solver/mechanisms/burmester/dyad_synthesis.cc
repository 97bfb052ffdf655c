#include <mechanisms/burmester/dyad_synthesis.h>

#include <cmath>
#include <stdexcept>

namespace compliant
{
  namespace burmester
  {
    namespace
    {
      Complex unit(const double angle) { return std::polar(1.0, angle); }
      Complex point(const PrecisionPosition &p) { return {p.x, p.y}; }
      constexpr double pi = 3.14159265358979323846;
    } // namespace

    CompatibilityCoefficients compatibility_coefficients(const std::vector<PrecisionPosition> &positions)
    {
      if (positions.size() != 4)
        throw std::invalid_argument("Burmester synthesis needs exactly four precision positions, got " +
                                    std::to_string(positions.size()));
      std::array<Complex, 5> a, d; // e^{i alpha_j} - 1 and delta_j
      for (unsigned int j = 2; j <= 4; ++j)
        {
          a[j] = unit(positions[j - 1].angle - positions[0].angle) - 1.0;
          d[j] = point(positions[j - 1]) - point(positions[0]);
        }
      CompatibilityCoefficients c;
      // Cofactors of the first column of [e^{i beta_j} - 1, e^{i alpha_j} - 1, delta_j].
      c.delta[2] = a[3] * d[4] - a[4] * d[3];
      c.delta[3] = a[4] * d[2] - a[2] * d[4];
      c.delta[4] = a[2] * d[3] - a[3] * d[2];
      c.delta[1] = -(c.delta[2] + c.delta[3] + c.delta[4]);
      return c;
    }

    std::vector<Dyad> dyads_for_beta2(const std::vector<PrecisionPosition> &positions, const double beta2)
    {
      const auto  c = compatibility_coefficients(positions);
      const auto &D = c.delta;
      // Delta3 e^{i b3} + Delta4 e^{i b4} = C closes a triangle of sides |Delta3|, |Delta4|, |C|.
      const Complex C  = -(D[1] + D[2] * unit(beta2));
      const double  a3 = std::abs(D[3]), a4 = std::abs(D[4]), c_abs = std::abs(C);
      std::vector<Dyad> dyads;
      if (a3 == 0 || a4 == 0 || c_abs == 0)
        return dyads;
      const double cos_phi = (a3 * a3 + c_abs * c_abs - a4 * a4) / (2 * a3 * c_abs);
      if (std::abs(cos_phi) > 1)
        return dyads; // no real closure for this beta2
      const double phi = std::acos(cos_phi);
      const double scale = std::abs(positions[1].x - positions[0].x) + std::abs(positions[1].y - positions[0].y) +
                           std::abs(positions[3].x - positions[0].x) + std::abs(positions[3].y - positions[0].y);
      for (const double sign : {1.0, -1.0})
        {
          Dyad dyad;
          dyad.beta2 = beta2;
          const double beta3 = std::arg(C) + sign * phi - std::arg(D[3]);
          const double beta4 = std::arg(C - D[3] * unit(beta3)) - std::arg(D[4]);
          dyad.beta = {0.0, beta2, beta3, beta4};
          // The trivial solution: the link turns with the coupler (beta_j = alpha_j).
          bool trivial = true;
          for (unsigned int j = 1; j < 4; ++j)
            trivial = trivial && std::abs(std::remainder(dyad.beta[j] - (positions[j].angle - positions[0].angle),
                                                          2 * pi)) < 1e-9;
          if (trivial)
            continue;
          // W and Z from the equations j = 2 and 3 (Cramer's rule).
          const Complex b2 = unit(beta2) - 1.0, b3 = unit(beta3) - 1.0;
          const Complex al2 = unit(positions[1].angle - positions[0].angle) - 1.0;
          const Complex al3 = unit(positions[2].angle - positions[0].angle) - 1.0;
          const Complex d2 = point(positions[1]) - point(positions[0]);
          const Complex d3 = point(positions[2]) - point(positions[0]);
          const Complex det = b2 * al3 - b3 * al2;
          if (std::abs(det) < 1e-14)
            continue;
          dyad.W            = (d2 * al3 - d3 * al2) / det;
          dyad.Z            = (b2 * d3 - b3 * d2) / det;
          dyad.circle_point = point(positions[0]) - dyad.Z;
          dyad.centre_point = dyad.circle_point - dyad.W;
          if (!std::isfinite(std::abs(dyad.W)) || !std::isfinite(std::abs(dyad.Z)) ||
              dyad_residual(positions, dyad) > 1e-8 * (1 + scale + std::abs(dyad.W) + std::abs(dyad.Z)))
            continue; // near-singular closure: the equations are not met, so it is no dyad
          dyads.push_back(dyad);
        }
      return dyads;
    }

    std::vector<Dyad> burmester_curves(const std::vector<PrecisionPosition> &positions, const unsigned int n)
    {
      std::vector<Dyad> all;
      for (unsigned int k = 0; k < n; ++k)
        {
          // beta2 = pi u^3, u uniform in (-1, 1): dense near beta2 = 0, where the positions' small
          // rotations (a few degrees here) put the long, practical links; never exactly 0 (no motion).
          const double u     = -1 + 2 * (k + 0.5) / n;
          const double beta2 = pi * u * u * u;
          for (const auto &d : dyads_for_beta2(positions, beta2))
            all.push_back(d);
        }
      return all;
    }

    PivotFit best_single_pivot(const std::vector<PrecisionPosition> &positions)
    {
      // R_j - e^{i alpha_j} R_1 = c (1 - e^{i alpha_j}): linear least squares in c.
      Complex num = 0;
      double  den = 0;
      for (const auto &p : positions)
        {
          const Complex e = unit(p.angle - positions[0].angle);
          num += std::conj(1.0 - e) * (point(p) - e * point(positions[0]));
          den += std::norm(1.0 - e);
        }
      PivotFit fit{den > 0 ? num / den : Complex(0, 0), 0, 0};
      fit.radius = std::abs(point(positions[0]) - fit.centre);
      for (const auto &p : positions)
        fit.position_error = std::max(fit.position_error,
                                      std::abs(point(p) - (fit.centre + unit(p.angle - positions[0].angle) *
                                                                            (point(positions[0]) - fit.centre))));
      return fit;
    }

    double dyad_residual(const std::vector<PrecisionPosition> &positions, const Dyad &dyad)
    {
      double worst = 0;
      for (unsigned int j = 1; j < 4; ++j)
        {
          const Complex lhs = dyad.W * (unit(dyad.beta[j]) - 1.0) +
                              dyad.Z * (unit(positions[j].angle - positions[0].angle) - 1.0);
          worst = std::max(worst, std::abs(lhs - (point(positions[j]) - point(positions[0]))));
        }
      return worst;
    }
  } // namespace burmester
} // namespace compliant
