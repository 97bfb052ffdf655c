// Four-position dyad synthesis (Burmester theory; morphing-wing paper, seed 001, Eq. 1-7; Sandor &
// Erdman, Advanced Mechanism Design, sec. 3.6). A dyad is a ground pivot M and a moving pivot K joined
// by a link; its coupler carries the precision point R. In the standard form
//   W (e^{i beta_j} - 1) + Z (e^{i alpha_j} - 1) = delta_j,   j = 2, 3, 4,
// W = K_1 - M is the link, Z = R_1 - K_1 the coupler side, alpha_j = theta_j - theta_1 the coupler
// rotations, delta_j = R_j - R_1, beta_j the link rotations. For four positions the three
// equations are compatible only if  Delta2 e^{i b2} + Delta3 e^{i b3} + Delta4 e^{i b4} + Delta1 = 0;
// sweeping beta2 traces the centre-point (M) and circle-point (K) curves.
#pragma once

#include <array>
#include <complex>
#include <vector>

namespace compliant
{
  namespace burmester
  {
    using Complex = std::complex<double>;

    struct PrecisionPosition
    {
      double x, y;  // the coupler point R_j
      double angle; // orientation of the coupler (radians)
    };

    struct CompatibilityCoefficients
    {
      std::array<Complex, 5> delta; // Delta1 .. Delta4 at indices 1..4 (index 0 unused)
    };
    // Eq. 2-7. Throws std::invalid_argument unless exactly four positions are given.
    CompatibilityCoefficients compatibility_coefficients(const std::vector<PrecisionPosition> &positions);

    struct Dyad
    {
      std::array<double, 4> beta; // link rotations from position 1 (beta[0] = 0)
      Complex               W, Z;
      Complex               centre_point; // M, the ground pivot
      Complex               circle_point; // K at position 1, the moving pivot
      double                beta2;
    };

    // The non-trivial dyads for one beta2 (0, 1 or 2: the two closures of the compatibility
    // triangle, minus the trivial solution beta_j = alpha_j, which makes the link the coupler).
    std::vector<Dyad> dyads_for_beta2(const std::vector<PrecisionPosition> &positions, double beta2);

    // Every dyad on a sweep of beta2 over (-pi, pi) with n samples, denser near 0: the Burmester curves.
    std::vector<Dyad> burmester_curves(const std::vector<PrecisionPosition> &positions, unsigned int n);

    // The single fixed pivot whose pure rotation best carries the coupler through the positions
    // (least squares in the centre, the rotations being the given ones). When its error is small,
    // one revolute joint does the job and the Burmester curves collapse around that point.
    struct PivotFit
    {
      Complex centre;
      double  radius;          // |R_1 - centre|
      double  position_error;  // largest |R_j - rotated R_1| over the positions
    };
    PivotFit best_single_pivot(const std::vector<PrecisionPosition> &positions);

    // Largest |W (e^{i beta_j} - 1) + Z (e^{i alpha_j} - 1) - delta_j| over j = 2, 3, 4 (a length).
    double dyad_residual(const std::vector<PrecisionPosition> &positions, const Dyad &dyad);
  } // namespace burmester
} // namespace compliant
