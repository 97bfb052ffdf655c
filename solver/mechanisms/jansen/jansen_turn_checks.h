// Consistency measures of the position analysis over a full crank turn.
#pragma once

#include <mechanisms/jansen/jansen_position_analysis.h>

namespace compliant
{
  namespace jansen
  {
    struct TurnChecks
    {
      double max_loop_residual = 0.;  // largest |loop_closure_residuals| entry, length units
      double max_length_error  = 0.;  // largest | |X - Y| - link length | over the 12 links
      double min_dyad_sine     = 1.;  // smallest |sin| of the angle at a dyad's free joint:
                                      // 0 would be a dead point where the branch can flip
      double theta2_of_min_dyad_sine = 0.; // rad
      char   joint_of_min_dyad_sine  = ' ';
    };

    // Evaluates the measures at theta2 = 2 pi i / n_steps, i = 0..n_steps-1.
    // Throws std::invalid_argument if n_steps < 1.
    TurnChecks check_crank_turn(const JansenLinkLengths &lengths,
                                const unsigned int       n_steps,
                                const AssemblyBranches  &branches = AssemblyBranches());
  } // namespace jansen
} // namespace compliant
