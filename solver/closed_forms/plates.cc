#include "plates.h"

#include <cmath>

namespace closed_forms
{
  namespace
  {
    double plate_rigidity(const double t, const double E, const double nu)
    {
      return E * t * t * t / (12 * (1 - nu * nu));
    }
  } // namespace

  double plate_buckling_stress(const double a, const double b, const double t, const double E, const double nu,
                               const double m, const double n)
  {
    const double k = std::pow(m * b / a + n * n * a / (m * b), 2);
    return k * M_PI * M_PI * plate_rigidity(t, E, nu) / (b * b * t);
  }

  double plate_buckling_shear_share(const double a, const double b, const double t, const double E, const double nu,
                                    const double m, const double n, const double kappa)
  {
    const double G = E / (2 * (1 + nu));
    return M_PI * M_PI * plate_rigidity(t, E, nu) * (m * m / (a * a) + n * n / (b * b)) / (kappa * G * t);
  }
} // namespace closed_forms
