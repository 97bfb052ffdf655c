// Markdown report of the Jansen leg kinematics: the ground-contact pose (foot
// lowest) and the seed paper's own pose theta2 = 302.8 deg, every angle, rate
// and foot velocity/acceleration beside the paper's printed numbers, checked
// by finite differences of the position analysis.
#pragma once

#include <mechanisms/jansen/jansen_link_lengths.h>
#include <mechanisms/jansen/jansen_position_analysis.h>

#include <ostream>

namespace compliant
{
  namespace jansen
  {
    struct ReportSettings
    {
      double       omega2           = 10.;  // crank speed, rad/s (the paper's)
      unsigned int n_check_steps    = 3600; // crank angles of the full-turn consistency checks
      double       finite_diff_step = 1e-3; // crank-angle step of the finite differences, rad
      double       stance_tolerance = 2.;   // foot height above its lowest that counts as stance, mm
    };

    void write_report(std::ostream            &out,
                      const JansenLinkLengths &lengths,
                      const ReportSettings    &settings = ReportSettings(),
                      const AssemblyBranches  &branches = AssemblyBranches());
  } // namespace jansen
} // namespace compliant
