// Lame's thick cylinder checked against its own defining equations, independently of how the
// formula is written: the displacement's strains through Hooke's law must give the stated
// stresses, the boundary stresses must equal minus the pressures, and the thin-wall limit must be
// the membrane (Barlow) stress p a / t.
#include <closed_forms/cylinders.h>

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using namespace closed_forms;

namespace
{
  constexpr double a = 10, b = 16, p_i = 3, p_o = 1.2, E = 210e3, nu = 0.3;

  // sigma_r, sigma_theta from u(r) by central differences and Hooke's law (plane strain or stress).
  void stresses_from_displacement(const double r, const bool plane_strain, double &sigma_r,
                                  double &sigma_theta)
  {
    const double h = 1e-4 * r;
    const auto   u = [&](double x) { return lame_radial_displacement(a, b, p_i, p_o, E, nu, x, plane_strain); };
    const double eps_r = (u(r + h) - u(r - h)) / (2 * h), eps_t = u(r) / r;
    if (plane_strain)
      {
        const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
        sigma_r     = lambda * (eps_r + eps_t) + 2 * mu * eps_r;
        sigma_theta = lambda * (eps_r + eps_t) + 2 * mu * eps_t;
      }
    else
      {
        sigma_r     = E / (1 - nu * nu) * (eps_r + nu * eps_t);
        sigma_theta = E / (1 - nu * nu) * (eps_t + nu * eps_r);
      }
  }
} // namespace

TEST(LameCylinder, DisplacementGivesTheStatedStressesInBothPlaneModels)
{
  for (const bool plane_strain : {true, false})
    for (const double r : {10.1, 12.0, 15.9})
      {
        double sigma_r, sigma_theta;
        stresses_from_displacement(r, plane_strain, sigma_r, sigma_theta);
        EXPECT_NEAR(sigma_r, lame_radial_stress(a, b, p_i, p_o, r), 1e-6) << r;
        EXPECT_NEAR(sigma_theta, lame_hoop_stress(a, b, p_i, p_o, r), 1e-6) << r;
      }
}

TEST(LameCylinder, BoundaryStressesAreMinusThePressures)
{
  EXPECT_NEAR(lame_radial_stress(a, b, p_i, p_o, a), -p_i, 1e-12);
  EXPECT_NEAR(lame_radial_stress(a, b, p_i, p_o, b), -p_o, 1e-12);
}

TEST(LameCylinder, ThinWallLimitIsTheMembraneStress)
{
  const double radius = 100, t = 0.01; // t / a = 1e-4: the hoop stress is p a / t to O(t/a)
  const double hoop = lame_hoop_stress(radius, radius + t, 1.0, 0.0, radius + t / 2);
  EXPECT_NEAR(hoop / (1.0 * radius / t), 1.0, 1e-3);
}

TEST(LameCylinder, RefusesRadiiOutsideTheWall)
{
  EXPECT_THROW(lame_radial_displacement(a, a, p_i, 0, E, nu, a, true), std::invalid_argument);
  EXPECT_THROW(lame_radial_displacement(a, b, p_i, 0, E, nu, b + 1, true), std::invalid_argument);
  EXPECT_THROW(lame_hoop_stress(a, b, p_i, 0, a / 2), std::invalid_argument);
}
