#include <mechanisms/four_bar/branch_tracker.h>
#include <mechanisms/four_bar/derivative_coefficients.h>
#include <mechanisms/four_bar/working_window.h>

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
      // cos(mu) = cos(th4 - th3): zero at a right transmission angle.
      double cos_transmission(const LinkLengths &lengths, const double crank_angle,
                              const AssemblyBranch branch)
      {
        const Pose pose = solve_pose(lengths, crank_angle, branch);
        return std::cos(pose.rocker_angle - pose.coupler_angle);
      }
    } // namespace

    double crank_angle_with_right_transmission(const LinkLengths   &lengths,
                                               const AssemblyBranch branch)
    {
      const unsigned int n_steps   = 1440;
      double             best      = std::numeric_limits<double>::quiet_NaN();
      double             best_rate = -1.;
      for (unsigned int i = 0; i < n_steps; ++i)
        {
          double lo = -M_PI + 2. * M_PI * i / n_steps, hi = -M_PI + 2. * M_PI * (i + 1) / n_steps;
          double f_lo, f_hi;
          try
            {
              f_lo = cos_transmission(lengths, lo, branch);
              f_hi = cos_transmission(lengths, hi, branch);
            }
          catch (const std::domain_error &)
            {
              continue; // crank position outside the assembly range
            }
          if (!(f_lo * f_hi <= 0.) || f_lo == f_hi)
            continue;
          for (unsigned int iteration = 0; iteration < 100 && hi - lo > 1e-14; ++iteration)
            {
              const double mid   = 0.5 * (lo + hi);
              const double f_mid = cos_transmission(lengths, mid, branch);
              if (f_lo * f_mid <= 0.)
                hi = mid;
              else
                {
                  lo   = mid;
                  f_lo = f_mid;
                }
            }
          const double root = 0.5 * (lo + hi);
          const double rate = std::abs(
            derivative_coefficients(lengths, solve_pose(lengths, root, branch)).rocker_velocity);
          if (rate > best_rate)
            {
              best_rate = rate;
              best      = root;
            }
        }
      if (!std::isfinite(best))
        throw std::domain_error("four_bar: the transmission angle never reaches 90 deg");
      return best;
    }

    double rocker_sweep_over(const LinkLengths &lengths, const AssemblyBranch branch,
                             const double crank_centre, const double crank_sweep,
                             const unsigned int n_samples)
    {
      // Track outwards from the centre in both directions so that the branch is the one the
      // mechanism has at the centre.
      double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
      for (const double direction : {+1., -1.})
        {
          BranchTracker tracker(lengths, crank_centre, branch);
          lowest  = std::min(lowest, tracker.pose().rocker_angle);
          highest = std::max(highest, tracker.pose().rocker_angle);
          for (unsigned int i = 1; i <= n_samples / 2; ++i)
            {
              const Pose &pose =
                tracker.advance(crank_centre + direction * 0.5 * crank_sweep * i / (n_samples / 2));
              lowest  = std::min(lowest, pose.rocker_angle);
              highest = std::max(highest, pose.rocker_angle);
            }
        }
      return highest - lowest;
    }

    double crank_sweep_for_rocker_sweep(const LinkLengths &lengths, const AssemblyBranch branch,
                                        const double crank_centre, const double rocker_sweep)
    {
      if (!(std::isfinite(rocker_sweep) && rocker_sweep > 0.))
        throw std::invalid_argument("four_bar: target rocker sweep must be positive");
      // Largest window: grow until the target is passed or the chain cannot be closed.
      double lo = 0., hi = 0.;
      for (double trial = 1e-3; trial <= 2. * M_PI; trial *= 1.5)
        {
          double sweep;
          try
            {
              sweep = rocker_sweep_over(lengths, branch, crank_centre, trial);
            }
          catch (const std::domain_error &)
            {
              break;
            }
          if (sweep >= rocker_sweep)
            {
              hi = trial;
              break;
            }
          lo = trial;
        }
      if (hi == 0.)
        throw std::domain_error("four_bar: no crank window around the given centre gives the "
                                "requested rocker sweep");
      for (unsigned int iteration = 0; iteration < 200 && hi - lo > 1e-12; ++iteration)
        {
          const double mid = 0.5 * (lo + hi);
          if (rocker_sweep_over(lengths, branch, crank_centre, mid) < rocker_sweep)
            lo = mid;
          else
            hi = mid;
        }
      return 0.5 * (lo + hi);
    }

    double min_collinearity_over(const LinkLengths &lengths, const AssemblyBranch branch,
                                 const double crank_start, const double crank_end,
                                 const unsigned int n_samples)
    {
      BranchTracker tracker(lengths, crank_start, branch);
      double        smallest =
        std::abs(std::sin(tracker.pose().coupler_angle - tracker.pose().rocker_angle));
      for (unsigned int i = 1; i <= n_samples; ++i)
        {
          const Pose &pose =
            tracker.advance(crank_start + (crank_end - crank_start) * i / n_samples);
          smallest = std::min(smallest, std::abs(std::sin(pose.coupler_angle - pose.rocker_angle)));
        }
      return smallest;
    }
  } // namespace four_bar
} // namespace compliant
