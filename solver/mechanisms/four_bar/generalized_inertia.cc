#include <mechanisms/four_bar/generalized_inertia.h>

#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace four_bar
  {
    namespace
    {
      using Complex = std::complex<double>;
      const Complex i_unit(0., 1.);

      Complex direction(const double angle)
      {
        return std::polar(1., angle);
      }

      // Centre positions r_k as complex numbers and their first and second derivatives with
      // respect to th2 (r' and r''), k = crank, coupler, rocker.
      struct CentreKinematics
      {
        std::array<Complex, 3> position, first, second;
      };

      CentreKinematics centre_kinematics(const LinkLengths &l, const MovingLinkMasses &m,
                                         const Pose &pose, const DerivativeCoefficients &h)
      {
        const Complex e2 = direction(pose.crank_angle), e3 = direction(pose.coupler_angle),
                      e4 = direction(pose.rocker_angle);
        const double c2 = m.crank.centre_offset, c3 = m.coupler.centre_offset,
                     c4 = m.rocker.centre_offset;
        const double h3 = h.coupler_velocity, h4 = h.rocker_velocity, g3 = h.coupler_acceleration,
                     g4 = h.rocker_acceleration;

        CentreKinematics k;
        k.position = {c2 * e2, l.crank * e2 + c3 * e3, l.ground + c4 * e4};
        k.first = {i_unit * c2 * e2, i_unit * (l.crank * e2 + c3 * h3 * e3), i_unit * c4 * h4 * e4};
        k.second = {-c2 * e2, -l.crank * e2 + c3 * (i_unit * g3 - h3 * h3) * e3,
                    c4 * (i_unit * g4 - h4 * h4) * e4};
        return k;
      }

      void check_link(const char *name, const LinkMass &link)
      {
        if (!(std::isfinite(link.mass) && link.mass >= 0.))
          throw std::invalid_argument(std::string("four_bar: ") + name +
                                      " mass must be non-negative and finite");
        if (!(std::isfinite(link.centre_inertia) && link.centre_inertia >= 0.))
          throw std::invalid_argument(std::string("four_bar: ") + name +
                                      " moment of inertia must be non-negative and finite");
        if (!std::isfinite(link.centre_offset))
          throw std::invalid_argument(std::string("four_bar: ") + name +
                                      " centre-of-mass offset must be finite");
      }
    } // namespace

    void check_masses(const MovingLinkMasses &masses)
    {
      check_link("crank", masses.crank);
      check_link("coupler", masses.coupler);
      check_link("rocker", masses.rocker);
    }

    InertiaTerms generalized_inertia(const LinkLengths &lengths, const MovingLinkMasses &masses,
                                     const Pose &pose, const DerivativeCoefficients &h)
    {
      const auto   k            = centre_kinematics(lengths, masses, pose, h);
      const double link_mass[3] = {masses.crank.mass, masses.coupler.mass, masses.rocker.mass};
      // Rotation rate of each link per unit crank rotation and its derivative.
      const double rate[3]           = {1., h.coupler_velocity, h.rocker_velocity};
      const double rate_rate[3]      = {0., h.coupler_acceleration, h.rocker_acceleration};
      const double centre_inertia[3] = {masses.crank.centre_inertia, masses.coupler.centre_inertia,
                                        masses.rocker.centre_inertia};

      // E19-E22 / E35: J = sum m |r'|^2 + I_c (dth/dth2)^2;  J' by the product rule.
      InertiaTerms terms{0., 0.};
      for (unsigned int n = 0; n < 3; ++n)
        {
          terms.value +=
            link_mass[n] * std::norm(k.first[n]) + centre_inertia[n] * rate[n] * rate[n];
          terms.derivative += 2. * link_mass[n] * std::real(std::conj(k.first[n]) * k.second[n]) +
                              2. * centre_inertia[n] * rate[n] * rate_rate[n];
        }
      return terms;
    }

    double gravity_torque(const LinkLengths &lengths, const MovingLinkMasses &masses,
                          const Pose &pose, const DerivativeCoefficients &h,
                          const std::array<double, 2> &gravity)
    {
      const auto   k            = centre_kinematics(lengths, masses, pose, h);
      const double link_mass[3] = {masses.crank.mass, masses.coupler.mass, masses.rocker.mass};
      double       torque       = 0.;
      for (unsigned int n = 0; n < 3; ++n)
        torque -=
          link_mass[n] * (gravity[0] * std::real(k.first[n]) + gravity[1] * std::imag(k.first[n]));
      return torque;
    }

    double gravity_potential(const LinkLengths &lengths, const MovingLinkMasses &masses,
                             const Pose &pose, const std::array<double, 2> &gravity)
    {
      const auto   centres      = mass_centres(lengths, masses, pose);
      const double link_mass[3] = {masses.crank.mass, masses.coupler.mass, masses.rocker.mass};
      double       potential    = 0.;
      for (unsigned int n = 0; n < 3; ++n)
        potential -= link_mass[n] * (gravity[0] * centres[n][0] + gravity[1] * centres[n][1]);
      return potential;
    }

    std::array<std::array<double, 2>, 3>
    mass_centres(const LinkLengths &lengths, const MovingLinkMasses &masses, const Pose &pose)
    {
      const auto    crank_dir   = direction(pose.crank_angle);
      const auto    coupler_dir = direction(pose.coupler_angle);
      const auto    rocker_dir  = direction(pose.rocker_angle);
      const Complex r2          = masses.crank.centre_offset * crank_dir;
      const Complex r3 = lengths.crank * crank_dir + masses.coupler.centre_offset * coupler_dir;
      const Complex r4 = lengths.ground + masses.rocker.centre_offset * rocker_dir;
      return {{{r2.real(), r2.imag()}, {r3.real(), r3.imag()}, {r4.real(), r4.imag()}}};
    }
  } // namespace four_bar
} // namespace compliant
