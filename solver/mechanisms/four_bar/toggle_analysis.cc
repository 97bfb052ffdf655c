#include <mechanisms/four_bar/toggle_analysis.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace compliant
{
  namespace four_bar
  {
    namespace
    {
      constexpr double two_pi = 2. * M_PI;

      double diagonal(const LinkLengths &l, const double crank_angle)
      {
        const double s2 = l.ground * l.ground + l.crank * l.crank - 2. * l.ground * l.crank * std::cos(crank_angle);
        return std::sqrt(std::max(s2, 0.));
      }

      // Crank rotation from start, in the sweep's sense, to angle: in [0, 2 pi).
      double forward_distance(const double start, const double angle, const double sense)
      {
        const double d = std::fmod(sense * (angle - start), two_pi);
        return d < 0 ? d + two_pi : d;
      }
    } // namespace

    int assembly_sign(const std::array<double, 2> &b, const std::array<double, 2> &c,
                      const std::array<double, 2> &d)
    {
      const double cross = (d[0] - b[0]) * (c[1] - b[1]) - (d[1] - b[1]) * (c[0] - b[0]);
      return (cross > 0) - (cross < 0);
    }

    JointPositions assemble(const LinkLengths &lengths, const double crank_angle, const int sign)
    {
      check_link_lengths(lengths);
      const double l3 = lengths.coupler, l4 = lengths.rocker;
      const std::array<double, 2> b{lengths.crank * std::cos(crank_angle), lengths.crank * std::sin(crank_angle)};
      const std::array<double, 2> d{lengths.ground, 0.};
      const double                s     = diagonal(lengths, crank_angle);
      const double                slack = 1e-12 * lengths.longest();
      if (s > l3 + l4 + slack || s < std::abs(l3 - l4) - slack || s == 0.)
        throw std::domain_error("four_bar: the chain cannot be closed at crank angle " +
                                std::to_string(crank_angle) + " rad");
      // Angle DBC at B from the cosine rule; C turns off the diagonal to the side the sign asks for.
      const double psi = std::acos(std::clamp((l3 * l3 + s * s - l4 * l4) / (2. * l3 * s), -1., 1.));
      const double dir = std::atan2(d[1] - b[1], d[0] - b[0]) + (sign >= 0 ? psi : -psi);
      return {{0., 0.}, b, {b[0] + l3 * std::cos(dir), b[1] + l3 * std::sin(dir)}, d};
    }

    double transmission_angle_for_diagonal(const LinkLengths &lengths, const double s)
    {
      const double l3 = lengths.coupler, l4 = lengths.rocker;
      return std::acos(std::clamp((l3 * l3 + l4 * l4 - s * s) / (2. * l3 * l4), -1., 1.));
    }

    std::vector<double> toggle_crank_angles(const LinkLengths &lengths)
    {
      check_link_lengths(lengths);
      const double        l1 = lengths.ground, l2 = lengths.crank;
      std::vector<double> angles;
      for (const double s : {std::abs(lengths.coupler - lengths.rocker), lengths.coupler + lengths.rocker})
        {
          const double c = (l1 * l1 + l2 * l2 - s * s) / (2. * l1 * l2);
          if (std::abs(c) > 1.)
            continue;
          const double a = std::acos(c);
          angles.push_back(a);
          if (a > 0. && a < M_PI)
            angles.push_back(-a);
        }
      return angles;
    }

    CrankSweep analyse_crank_sweep(const LinkLengths &lengths, const double crank_start, const double travel)
    {
      check_link_lengths(lengths);
      if (!std::isfinite(crank_start) || !std::isfinite(travel) || std::abs(travel) > two_pi * (1 + 1e-12))
        throw std::invalid_argument("four_bar: a crank sweep needs a finite start and |travel| <= 2 pi");
      const double sense = travel >= 0 ? 1. : -1., length = std::abs(travel);

      // The diagonal's extremes: the sweep's ends, and th2 = 0 (shortest) or pi (longest) if passed.
      double s_min = std::min(diagonal(lengths, crank_start), diagonal(lengths, crank_start + travel));
      double s_max = std::max(diagonal(lengths, crank_start), diagonal(lengths, crank_start + travel));
      if (forward_distance(crank_start, 0., sense) <= length)
        s_min = std::abs(lengths.ground - lengths.crank);
      if (forward_distance(crank_start, M_PI, sense) <= length)
        s_max = lengths.ground + lengths.crank;

      CrankSweep sweep;
      sweep.mu_min              = transmission_angle_for_diagonal(lengths, s_min);
      sweep.mu_max              = transmission_angle_for_diagonal(lengths, s_max);
      sweep.transmission_margin = std::min(sweep.mu_min, M_PI - sweep.mu_max);
      sweep.closes_everywhere =
        s_min >= std::abs(lengths.coupler - lengths.rocker) && s_max <= lengths.coupler + lengths.rocker;

      sweep.crank_margin = std::numeric_limits<double>::infinity();
      for (const double toggle : toggle_crank_angles(lengths))
        {
          const double d = forward_distance(crank_start, toggle, sense);
          if (d <= length)
            {
              sweep.toggle_travel = sweep.toggle_inside ? std::min(sweep.toggle_travel, d) : d;
              sweep.toggle_inside = true;
            }
          else
            sweep.crank_margin = std::min({sweep.crank_margin, d - length, two_pi - d});
        }
      if (sweep.toggle_inside || !sweep.closes_everywhere)
        sweep.crank_margin = 0.;
      return sweep;
    }
  } // namespace four_bar
} // namespace compliant
