#include <mechanisms/burmester/candidate_mechanism.h>
#include <mechanisms/four_bar/toggle_analysis.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace compliant
{
  namespace burmester
  {
    namespace
    {
      constexpr double pi = 3.14159265358979323846;

      std::array<double, 2> point(const Complex z) { return {z.real(), z.imag()}; }
      Complex               complex(const std::array<double, 2> &p) { return {p[0], p[1]}; }

      std::string between(unsigned int j) // positions j and j + 1, counted from 1
      {
        return "between positions " + std::to_string(j) + " and " + std::to_string(j + 1);
      }
    } // namespace

    CandidateMechanism analyse_candidate(const std::vector<PrecisionPosition> &positions,
                                         const Dyad &input, const Dyad &output)
    {
      CandidateMechanism m;
      m.input  = input;
      m.output = output;
      const Complex A = input.centre_point, D = output.centre_point;
      const Complex B1 = input.circle_point, C1 = output.circle_point;
      const Complex R1(positions[0].x, positions[0].y);
      m.lengths   = {std::abs(D - A), std::abs(B1 - A), std::abs(C1 - B1), std::abs(C1 - D)};
      m.perimeter = m.lengths.ground + m.lengths.crank + m.lengths.coupler + m.lengths.rocker;
      const double scale = std::max(1e-12, m.lengths.longest());
      if (std::min({m.lengths.ground, m.lengths.crank, m.lengths.coupler, m.lengths.rocker}) < 1e-9 * scale)
        {
          m.defect = "degenerate: a link of zero length";
          return m;
        }
      m.grashof = four_bar::classify_grashof(m.lengths);
      const Complex frame = std::polar(1.0, -std::arg(D - A)); // global -> library frame (A origin, D on x)
      const double  phi1  = std::arg(C1 - B1);
      const Complex r_local = (R1 - B1) * std::polar(1.0, -phi1);

      // The coupler carries B and C rigidly from position 1: the input angle, the assembly and the
      // transmission angle at each position follow without any motion.
      std::array<double, 4> theta2;
      m.mu_min_at_positions = pi;
      m.mu_max_at_positions = 0;
      for (unsigned int j = 0; j < 4; ++j)
        {
          const Complex turn = std::polar(1.0, positions[j].angle - positions[0].angle);
          const Complex Rj(positions[j].x, positions[j].y);
          const Complex Bj = Rj + (B1 - R1) * turn, Cj = Rj + (C1 - R1) * turn;
          theta2[j]        = std::arg((Bj - A) * frame);
          m.assembly[j]    = four_bar::assembly_sign(point(Bj), point(Cj), point(D));
          const double mu  = four_bar::transmission_angle_for_diagonal(m.lengths, std::abs(Bj - D));
          m.mu_min_at_positions = std::min(m.mu_min_at_positions, mu);
          m.mu_max_at_positions = std::max(m.mu_max_at_positions, mu);
        }

      // Direction: the one (if any) in which the input meets the positions in order, the long way
      // round included; without one, the shorter way from position 1 to 2 (an order defect).
      std::array<double, 4> travel{0, 0, 0, 0};
      auto travels = [&](double sense) {
        std::array<double, 4> t{0, 0, 0, 0};
        for (unsigned int j = 1; j < 4; ++j)
          {
            const double a = sense * (theta2[j] - theta2[0]);
            t[j]           = a - 2 * pi * std::floor(a / (2 * pi));
          }
        return t;
      };
      auto in_order = [](const std::array<double, 4> &t) { return t[1] < t[2] && t[2] < t[3]; };
      double sense = std::remainder(theta2[1] - theta2[0], 2 * pi) >= 0 ? 1 : -1;
      if (!in_order(travels(sense)) && in_order(travels(-sense)))
        sense = -sense;
      travel        = travels(sense);
      m.input_sweep = sense * travel[3];

      const auto sweep = four_bar::analyse_crank_sweep(m.lengths, theta2[0], m.input_sweep);
      m.mu_min                     = sweep.mu_min;
      m.mu_max                     = sweep.mu_max;
      m.toggle_margin_transmission = sweep.transmission_margin;
      m.toggle_margin_input        = sweep.crank_margin;

      // Forward kinematics on position 1's assembly: where the coupler point lands at each position.
      for (unsigned int j = 0; j < 4 && m.assembly[0] != 0; ++j)
        try
          {
            const auto    joints = four_bar::assemble(m.lengths, theta2[j], m.assembly[0]);
            const Complex b = A + complex(joints.b) / frame, c = A + complex(joints.c) / frame;
            const double  coupler_dir = std::arg(c - b);
            const Complex r           = b + r_local * std::polar(1.0, coupler_dir);
            m.position_error = std::max(m.position_error, std::abs(r - Complex(positions[j].x, positions[j].y)));
            m.angle_error    = std::max(m.angle_error, std::abs(std::remainder(positions[0].angle + coupler_dir - phi1 -
                                                                                positions[j].angle, 2 * pi)));
          }
        catch (const std::domain_error &)
          {}

      if (!in_order(travel))
        m.defect = "order defect: the input passes the positions out of order";
      else if (sweep.toggle_inside || !sweep.closes_everywhere)
        {
          unsigned int j = 1;
          while (j < 3 && sweep.toggle_travel > travel[j])
            ++j;
          m.defect = "circuit defect: a dead point " + between(j) + " (the input cannot drive through)";
        }
      else
        for (unsigned int j = 0; j < 4 && m.defect.empty(); ++j)
          if (m.assembly[j] == 0)
            m.defect = "circuit defect: position " + std::to_string(j + 1) + " is a toggle";
          else if (m.assembly[j] != m.assembly[0])
            m.defect = "branch defect: position " + std::to_string(j + 1) +
                       " lies on the other assembly branch (no toggle between: the input cannot reach it)";
      m.defect_free = m.defect.empty();
      return m;
    }

    bool meets_paper_criteria(const CandidateMechanism &m, const SelectionCriteria &criteria)
    {
      const bool grashof = m.grashof.condition < 0;
      const auto   l       = m.lengths;
      const double shortest = std::min({l.ground, l.crank, l.coupler, l.rocker});
      return grashof && m.lengths.longest() <= criteria.max_link_length && shortest >= criteria.min_link_length &&
             m.mu_min_at_positions >= criteria.mu_low && m.mu_max_at_positions <= criteria.mu_high;
    }

    bool meets_all_criteria(const CandidateMechanism &m, const SelectionCriteria &criteria)
    {
      return meets_paper_criteria(m, criteria) && m.defect_free && m.mu_min >= criteria.mu_low &&
             m.mu_max <= criteria.mu_high;
    }
  } // namespace burmester
} // namespace compliant
