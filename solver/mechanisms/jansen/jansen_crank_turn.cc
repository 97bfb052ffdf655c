#include <mechanisms/jansen/jansen_crank_turn.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace compliant
{
  namespace jansen
  {
    JansenState analyse_state(const JansenLinkLengths &lengths,
                              const double             theta2,
                              const double             omega2,
                              const double             alpha2,
                              const AssemblyBranches  &branches)
    {
      JansenState state;
      state.theta2 = theta2;
      state.pose   = solve_position(lengths, theta2, branches);
      state.motion = solve_motion(lengths, state.pose.angles, omega2, alpha2);
      return state;
    }

    std::vector<JansenState> sweep_crank_turn(const JansenLinkLengths &lengths,
                                              const double             omega2,
                                              const unsigned int       n_steps,
                                              const AssemblyBranches  &branches)
    {
      if (n_steps < 1)
        throw std::invalid_argument("sweep_crank_turn: n_steps must be at least 1, got " +
                                    std::to_string(n_steps));
      std::vector<JansenState> states;
      states.reserve(n_steps + 1);
      for (unsigned int i = 0; i <= n_steps; ++i)
        states.push_back(
          analyse_state(lengths, 2. * M_PI * i / n_steps, omega2, 0., branches));
      return states;
    }

    namespace
    {
      // dy_H/d theta2 and d^2 y_H/d theta2^2: the foot's vertical velocity and
      // acceleration for a unit, constant crank speed.
      std::pair<double, double> foot_height_slope_and_curvature(const JansenLinkLengths &lengths,
                                                                const double             theta2,
                                                                const AssemblyBranches  &branches)
      {
        const JansenState state = analyse_state(lengths, theta2, 1., 0., branches);
        return {state.motion.velocities[Joint::H].y, state.motion.accelerations[Joint::H].y};
      }

      // Root of the slope in [lower, upper] where it goes from <= 0 to >= 0.
      double refine_minimum(const JansenLinkLengths &lengths,
                            double                   lower,
                            double                   upper,
                            const AssemblyBranches  &branches)
      {
        double guess = 0.5 * (lower + upper);
        for (unsigned int iteration = 0; iteration < 100 && upper - lower > 1e-15; ++iteration)
          {
            const auto [slope, curvature] =
              foot_height_slope_and_curvature(lengths, guess, branches);
            if (slope == 0.)
              return guess;
            (slope < 0. ? lower : upper) = guess;
            const double newton = guess - slope / curvature;
            const bool   inside = curvature > 0. && newton > lower && newton < upper;
            const double next   = inside ? newton : 0.5 * (lower + upper);
            if (std::abs(next - guess) < 1e-15)
              return next;
            guess = next;
          }
        return guess;
      }
    } // namespace

    GroundContact find_ground_contact(const JansenLinkLengths &lengths,
                                      const unsigned int       n_samples,
                                      const AssemblyBranches  &branches)
    {
      if (n_samples < 8)
        throw std::invalid_argument("find_ground_contact: n_samples must be at least 8, got " +
                                    std::to_string(n_samples));
      const double        step = 2. * M_PI / n_samples;
      std::vector<double> height(n_samples);
      for (unsigned int i = 0; i < n_samples; ++i)
        height[i] = solve_position(lengths, i * step, branches).positions[Joint::H].y;

      GroundContact contact;
      for (unsigned int i = 0; i < n_samples; ++i)
        {
          const double before = height[(i + n_samples - 1) % n_samples];
          const double after  = height[(i + 1) % n_samples];
          if (height[i] <= before && height[i] < after)
            {
              const double theta2 =
                refine_minimum(lengths, (i - 1.) * step, (i + 1.) * step, branches);
              FootLowPoint point;
              point.theta2 = theta2 - 2. * M_PI * std::floor(theta2 / (2. * M_PI));
              point.foot   = solve_position(lengths, point.theta2, branches).positions[Joint::H];
              contact.local_minima.push_back(point);
            }
        }
      std::sort(contact.local_minima.begin(),
                contact.local_minima.end(),
                [](const FootLowPoint &a, const FootLowPoint &b) { return a.foot.y < b.foot.y; });
      contact.lowest = contact.local_minima.front();
      return contact;
    }

    StanceInterval find_stance(const JansenLinkLengths &lengths,
                               const double             height_tolerance,
                               const unsigned int       n_samples,
                               const AssemblyBranches  &branches)
    {
      if (!(height_tolerance > 0. && std::isfinite(height_tolerance)))
        throw std::invalid_argument("find_stance: height_tolerance must be a positive length");
      if (n_samples < 8)
        throw std::invalid_argument("find_stance: n_samples must be at least 8, got " +
                                    std::to_string(n_samples));
      const GroundContact contact = find_ground_contact(lengths, 720, branches);
      const double        step    = 2. * M_PI / n_samples;
      const auto          in_stance = [&](const double theta2) {
        return solve_position(lengths, theta2, branches).positions[Joint::H].y <=
               contact.lowest.foot.y + height_tolerance;
      };
      // Walk backwards and forwards from the lowest point; stop after a full turn
      // (a foot path flat to within the tolerance everywhere).
      unsigned int before = 0, after = 0;
      while (before < n_samples && in_stance(contact.lowest.theta2 - (before + 1) * step))
        ++before;
      while (after < n_samples && in_stance(contact.lowest.theta2 + (after + 1) * step))
        ++after;

      StanceInterval stance;
      const double   start = contact.lowest.theta2 - before * step;
      const double   end   = contact.lowest.theta2 + after * step;
      const auto     wrap  = [](const double t) { return t - 2. * M_PI * std::floor(t / (2. * M_PI)); };
      stance.start_theta2  = wrap(start);
      stance.end_theta2    = wrap(end);
      stance.crank_sweep   = std::min(end - start, 2. * M_PI);
      stance.foot_travel   = solve_position(lengths, end, branches).positions[Joint::H].x -
                           solve_position(lengths, start, branches).positions[Joint::H].x;
      return stance;
    }
  } // namespace jansen
} // namespace compliant
