#include <mechanisms/burmester/candidate_mechanism.h>
#include <mechanisms/four_bar/branch_tracker.h>
#include <mechanisms/four_bar/position_analysis.h>

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

      struct GlobalPose
      {
        Complex b, c, coupler_point;
        double  coupler_orientation;
        double  transmission; // 0..pi
      };
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
      const double gamma = std::arg(D - A);             // ground line direction
      const double phi1  = std::arg(C1 - B1);           // coupler line at position 1
      const Complex r_local = (R1 - B1) * std::polar(1.0, -phi1);

      auto to_global = [&](const four_bar::Pose &pose) {
        const auto    joints = four_bar::joint_positions(m.lengths, pose);
        const Complex e      = std::polar(1.0, gamma);
        GlobalPose    g;
        g.b = A + e * Complex(joints.b[0], joints.b[1]);
        g.c = A + e * Complex(joints.c[0], joints.c[1]);
        const double coupler_dir = std::arg(g.c - g.b);
        g.coupler_point          = g.b + r_local * std::polar(1.0, coupler_dir);
        g.coupler_orientation    = positions[0].angle + (coupler_dir - phi1);
        g.transmission           = std::abs(four_bar::wrap_angle(pose.rocker_angle - pose.coupler_angle));
        return g;
      };

      // Input angle (library frame) at each position, and the branch that assembles position 1.
      std::array<double, 4> theta2;
      for (unsigned int j = 0; j < 4; ++j)
        theta2[j] = std::arg(input.W) + input.beta[j] - gamma;
      four_bar::AssemblyBranch branch = four_bar::AssemblyBranch::plus;
      double                   best   = 1e300;
      for (const auto b : {four_bar::AssemblyBranch::plus, four_bar::AssemblyBranch::minus})
        try
          {
            const double d = std::abs(to_global(four_bar::solve_pose(m.lengths, theta2[0], b)).c - C1);
            if (d < best)
              best = d, branch = b;
          }
        catch (const std::domain_error &)
          {}
      if (best > 1e-6 * scale)
        {
          m.defect = "position 1 does not assemble";
          return m;
        }

      // Direction: the way the input turns from position 1 to 2; the positions must follow in order.
      std::array<double, 4> travel{0, 0, 0, 0};
      const double          sense = std::remainder(theta2[1] - theta2[0], 2 * pi) >= 0 ? 1 : -1;
      for (unsigned int j = 1; j < 4; ++j)
        {
          double t = sense * (theta2[j] - theta2[0]);
          t        = t - 2 * pi * std::floor(t / (2 * pi));
          travel[j] = t;
        }
      m.input_sweep = sense * travel[3];
      if (!(travel[1] < travel[2] && travel[2] < travel[3]))
        m.defect = "order defect: the input passes the positions out of order";

      // Track the motion in steps of at most 0.5 degrees, through every position.
      four_bar::BranchTracker tracker(m.lengths, theta2[0], branch);
      m.mu_min = m.mu_min_at_positions = pi;
      m.mu_max = m.mu_max_at_positions = 0;
      auto record = [&](const GlobalPose &g) {
        m.mu_min = std::min(m.mu_min, g.transmission);
        m.mu_max = std::max(m.mu_max, g.transmission);
      };
      auto check_position = [&](const GlobalPose &g, unsigned int j) {
        m.position_error = std::max(m.position_error,
                                    std::abs(g.coupler_point - Complex(positions[j].x, positions[j].y)));
        m.angle_error    = std::max(m.angle_error,
                                    std::abs(std::remainder(g.coupler_orientation - positions[j].angle, 2 * pi)));
        m.mu_min_at_positions = std::min(m.mu_min_at_positions, g.transmission);
        m.mu_max_at_positions = std::max(m.mu_max_at_positions, g.transmission);
      };
      const GlobalPose first = to_global(tracker.pose());
      record(first);
      check_position(first, 0);
      const double step_max = 0.5 * pi / 180;
      double       done     = 0;
      for (unsigned int j = 1; j < 4 && m.defect.empty(); ++j)
        {
          const unsigned int steps = std::max(1u, static_cast<unsigned int>(std::ceil((travel[j] - done) / step_max)));
          const double       start = done;
          for (unsigned int s = 1; s <= steps; ++s)
            {
              const double angle = theta2[0] + sense * (start + (travel[j] - start) * s / steps);
              try
                {
                  record(to_global(tracker.advance(angle)));
                }
              catch (const std::domain_error &)
                {
                  m.defect = "circuit defect: a dead point between positions " + std::to_string(j) +
                             " and " + std::to_string(j + 1) + " (the input cannot drive through)";
                  break;
                }
            }
          if (!m.defect.empty())
            break;
          done = travel[j];
          const GlobalPose g = to_global(tracker.pose());
          check_position(g, j);
          if (std::abs(g.coupler_point - Complex(positions[j].x, positions[j].y)) > 1e-6 * scale)
            m.defect = "branch defect: position " + std::to_string(j + 1) +
                       " lies on the other assembly branch";
        }
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
