#include <mechanisms/four_bar/branch_tracker.h>
#include <mechanisms/four_bar/cycle_dynamics.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace four_bar
  {
    namespace
    {
      void check_mechanism(const FlapMechanism &mechanism)
      {
        check_link_lengths(mechanism.lengths);
        check_masses(mechanism.masses);
        for (const double K : mechanism.springs.stiffness)
          if (!(std::isfinite(K) && K >= 0.))
            throw std::invalid_argument("four_bar: spring stiffness must be non-negative");
        if (!std::isfinite(mechanism.gravity[0]) || !std::isfinite(mechanism.gravity[1]))
          throw std::invalid_argument("four_bar: gravity must be finite");
      }

      DerivativeCoefficients regular_coefficients(const LinkLengths &lengths, const Pose &pose)
      {
        const DerivativeCoefficients h = derivative_coefficients(lengths, pose);
        if (h.singular)
          {
            std::ostringstream message;
            message << "four_bar: dead point (coupler and rocker collinear) at crank angle "
                    << pose.crank_angle << " rad: the crank cannot drive the mechanism there";
            throw std::domain_error(message.str());
          }
        return h;
      }
    } // namespace

    std::vector<CycleSample> evaluate_cycle(const FlapMechanism &mechanism, const MotionLaw &motion,
                                            const double motor_speed, const unsigned int n_samples,
                                            const unsigned int n_motor_turns)
    {
      check_mechanism(mechanism);
      motion.check();
      if (!(std::isfinite(motor_speed) && motor_speed > 0.))
        throw std::invalid_argument("four_bar: motor speed must be positive");
      if (n_samples < 2 || n_motor_turns < 1)
        throw std::invalid_argument("four_bar: need at least 2 samples and 1 motor turn per cycle");

      const double             cycle = 2. * M_PI * n_motor_turns;
      std::vector<CycleSample> samples(n_samples);
      const double  first_crank_angle = motion.at(0.5 * cycle / n_samples, motor_speed).angle;
      BranchTracker tracker(mechanism.lengths, first_crank_angle, mechanism.branch);
      // Shift by whole turns so that the poses are unwrapped consistently with the springs'
      // rest pose (the spring rotations are differences of unwrapped angles).
      const double rocker_shift =
        unwrap_near(tracker.pose().rocker_angle, mechanism.springs.rest.rocker_angle) -
        tracker.pose().rocker_angle;
      const double coupler_shift =
        unwrap_near(tracker.pose().coupler_angle, mechanism.springs.rest.coupler_angle) -
        tracker.pose().coupler_angle;
      for (unsigned int j = 0; j < n_samples; ++j)
        {
          CycleSample &s = samples[j];
          s.motor_angle  = (j + 0.5) * cycle / n_samples;
          s.time         = s.motor_angle / motor_speed;
          s.crank        = motion.at(s.motor_angle, motor_speed);
          s.pose         = j == 0 ? tracker.pose() : tracker.advance(s.crank.angle);
          s.pose.rocker_angle += rocker_shift;
          s.pose.coupler_angle += coupler_shift;
          s.coefficients       = regular_coefficients(mechanism.lengths, s.pose);
          s.transmission_angle = transmission_angle(s.pose);

          const InertiaTerms J =
            generalized_inertia(mechanism.lengths, mechanism.masses, s.pose, s.coefficients);
          const double w2 = s.crank.velocity, a2 = s.crank.acceleration;
          s.inertia_torque = J.value * a2 + 0.5 * J.derivative * w2 * w2;
          s.gravity_torque = four_bar::gravity_torque(mechanism.lengths, mechanism.masses, s.pose,
                                                      s.coefficients, mechanism.gravity);
          s.spring_torque  = input_torque_virtual_work(mechanism.springs, s.pose, s.coefficients);
          s.kinetic_energy = 0.5 * J.value * w2 * w2;
          s.gravity_energy =
            gravity_potential(mechanism.lengths, mechanism.masses, s.pose, mechanism.gravity);
          s.spring_energy = four_bar::spring_energy(mechanism.springs, s.pose);
        }
      return samples;
    }

    TorqueStatistics torque_statistics(const std::vector<CycleSample> &samples,
                                       const TorqueComponent           component,
                                       const TorqueReference           reference)
    {
      if (samples.empty())
        throw std::invalid_argument("four_bar: torque statistics of an empty cycle");
      TorqueStatistics stats{0., 0., 0., 0., 0.};
      double           lowest = samples.front().inertia_torque, highest = lowest;
      bool             first = true;
      for (const CycleSample &s : samples)
        {
          double crank_torque = 0.;
          switch (component)
            {
              case TorqueComponent::inertia:
                crank_torque = s.inertia_torque;
                break;
              case TorqueComponent::rigid:
                crank_torque = s.rigid_crank_torque();
                break;
              case TorqueComponent::springs:
                crank_torque = s.spring_torque;
                break;
              case TorqueComponent::compliant:
                crank_torque = s.compliant_crank_torque();
                break;
            }
          // Power is the same at crank and motor (ideal driver): T_crank w2 = T_motor w.
          const double power = crank_torque * s.crank.velocity;
          const double torque =
            reference == TorqueReference::crank ? crank_torque : crank_torque * s.crank.drive_ratio;
          if (first)
            lowest = highest = torque;
          first      = false;
          lowest     = std::min(lowest, torque);
          highest    = std::max(highest, torque);
          stats.peak = std::max(stats.peak, std::abs(torque));
          stats.rms += torque * torque;
          stats.peak_power = std::max(stats.peak_power, std::abs(power));
          stats.rms_power += power * power;
        }
      stats.rms       = std::sqrt(stats.rms / samples.size());
      stats.rms_power = std::sqrt(stats.rms_power / samples.size());
      stats.range     = highest - lowest;
      return stats;
    }

    ReflectedLoad reflected_load(const FlapMechanism &mechanism, const MotionLaw &motion,
                                 const double motor_angle, const bool include_springs)
    {
      // Unit motor speed: only the geometric drive ratios s, s' are used.
      const CrankState crank         = motion.at(motor_angle, 1.);
      const Pose       pose          = solve_pose(mechanism.lengths, crank.angle, mechanism.branch);
      const DerivativeCoefficients h = regular_coefficients(mechanism.lengths, pose);
      const InertiaTerms J = generalized_inertia(mechanism.lengths, mechanism.masses, pose, h);
      double             dV =
        four_bar::gravity_torque(mechanism.lengths, mechanism.masses, pose, h, mechanism.gravity);
      if (include_springs)
        {
          // The springs' rest pose may be unwrapped differently from solve_pose's (-pi, pi].
          Pose unwrapped = pose;
          unwrapped.rocker_angle =
            unwrap_near(pose.rocker_angle, mechanism.springs.rest.rocker_angle);
          unwrapped.coupler_angle =
            unwrap_near(pose.coupler_angle, mechanism.springs.rest.coupler_angle);
          dV += input_torque_virtual_work(mechanism.springs, unwrapped, h);
        }
      const double s = crank.drive_ratio, ds = crank.drive_ratio_derivative;
      return {J.value * s * s, J.derivative * s * s * s + 2. * J.value * s * ds, dV * s};
    }
  } // namespace four_bar
} // namespace compliant
