// The leg over a full crank turn and its ground-contact pose.
#pragma once

#include <mechanisms/jansen/jansen_motion_analysis.h>
#include <mechanisms/jansen/jansen_position_analysis.h>

#include <vector>

namespace compliant
{
  namespace jansen
  {
    // Position, velocity and acceleration at one crank angle.
    struct JansenState
    {
      double       theta2 = 0.; // rad
      JansenPose   pose;
      JansenMotion motion;
    };

    JansenState analyse_state(const JansenLinkLengths &lengths,
                              const double             theta2,
                              const double             omega2,
                              const double             alpha2   = 0.,
                              const AssemblyBranches  &branches = AssemblyBranches());

    // n_steps + 1 states at theta2 = 2 pi i / n_steps, i = 0..n_steps (the last
    // repeats the first so that the foot path closes), constant crank speed
    // omega2. Throws std::invalid_argument if n_steps < 1.
    std::vector<JansenState> sweep_crank_turn(const JansenLinkLengths &lengths,
                                              const double             omega2,
                                              const unsigned int       n_steps,
                                              const AssemblyBranches  &branches = AssemblyBranches());

    struct FootLowPoint
    {
      double       theta2 = 0.; // rad, in [0, 2 pi)
      PlanarVector foot;
    };

    struct GroundContact
    {
      FootLowPoint              lowest;       // the ground-contact pose: H lowest
      std::vector<FootLowPoint> local_minima; // all minima of y_H(theta2), lowest first
    };

    // Samples y_H at n_samples crank angles, then refines every discrete
    // minimum to the root of dy_H/d theta2 (the analytic foot velocity at
    // omega2 = 1) by Newton steps safeguarded with bisection, to round-off.
    // Jansen's stance is nearly flat, so y_H may have several local minima a
    // fraction of a millimetre apart: all are returned. Throws
    // std::invalid_argument if n_samples < 8.
    GroundContact find_ground_contact(const JansenLinkLengths &lengths,
                                      const unsigned int       n_samples = 720,
                                      const AssemblyBranches  &branches  = AssemblyBranches());

    // The stance: the contiguous crank-angle interval around the lowest foot
    // position in which H stays within height_tolerance of its lowest height
    // (a flat ground touching the lowest point). Found on n_samples crank
    // angles, so its ends are accurate to 2 pi / n_samples. Throws
    // std::invalid_argument for a non-positive tolerance or n_samples < 8.
    struct StanceInterval
    {
      double start_theta2 = 0.; // rad, in [0, 2 pi): where the foot comes down within tolerance
      double end_theta2   = 0.; // rad, in [0, 2 pi): where it rises above it again
      double crank_sweep  = 0.; // rad, the crank rotation spent in stance (counter-clockwise)
      double foot_travel  = 0.; // x_H(end) - x_H(start), length units
    };

    StanceInterval find_stance(const JansenLinkLengths &lengths,
                               const double             height_tolerance,
                               const unsigned int       n_samples = 3600,
                               const AssemblyBranches  &branches  = AssemblyBranches());
  } // namespace jansen
} // namespace compliant
