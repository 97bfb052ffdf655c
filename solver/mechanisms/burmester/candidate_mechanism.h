// A four-bar built from two Burmester dyads, checked with the four-bar library: does the input link,
// turning one way, carry the coupler through the four precision positions in order, on one assembly
// branch, without a dead point (order, branch and circuit defects, the known failings of Burmester
// synthesis; Chase & Mirth 1993; Balli & Chand 2002), and what transmission angle does it have over
// that whole motion? Decided exactly, not by a stepped motion: the assembly at each position is the
// side of the diagonal B -> D on which C lies (the coupler carries B and C there), and the absence
// of a toggle between the positions follows from the diagonal's extremes over the input's sweep
// (four_bar/toggle_analysis.h). A stepped tracker hops between assemblies near a toggle.
#pragma once

#include <mechanisms/burmester/dyad_synthesis.h>
#include <mechanisms/four_bar/grashof.h>
#include <mechanisms/four_bar/link_lengths.h>

#include <array>
#include <string>
#include <vector>

namespace compliant
{
  namespace burmester
  {
    struct CandidateMechanism
    {
      Dyad                       input, output; // input: the driven link (crank) is input.W
      four_bar::LinkLengths      lengths;
      four_bar::GrashofAnalysis  grashof;
      double                     perimeter = 0;
      // Transmission angle (0..180 degrees, between coupler and output link) at the positions and
      // over the whole motion from position 1 to 4.
      double mu_min_at_positions = 0, mu_max_at_positions = 0;
      double mu_min = 0, mu_max = 0;
      double input_sweep = 0; // radians turned by the input from position 1 to 4 (signed)
      // Distance to the nearest toggle over the motion: in transmission angle, min(mu_min, pi - mu_max),
      // and in input rotation beyond the motion's ends (infinite if the input turns fully without one).
      double toggle_margin_transmission = 0, toggle_margin_input = 0;
      // Assembly (side of B -> D on which C lies, +1 or -1) at each position, as the coupler places B and C.
      std::array<int, 4> assembly{0, 0, 0, 0};
      // Forward kinematics at the four positions: largest coupler point and orientation errors.
      double position_error = 0, angle_error = 0;
      bool        defect_free = false;
      std::string defect; // empty, or which defect and where
    };

    struct SelectionCriteria
    {
      double mu_low  = 40 * 3.14159265358979323846 / 180; // paper: 40 < mu < 140 degrees
      double mu_high = 140 * 3.14159265358979323846 / 180;
      double max_link_length = 1.0;  // chords; the paper bounds the mechanism by the wing section
      double min_link_length = 0.02; // chords; shorter links are points, not parts to build
    };

    // The pair as a four-bar driven by the input dyad's link, through the motion from position 1 to 4.
    CandidateMechanism analyse_candidate(const std::vector<PrecisionPosition> &positions,
                                         const Dyad &input, const Dyad &output);

    // The paper's filter (its Eq. 8-9 at the positions, links within the bound), without defect checks.
    bool meets_paper_criteria(const CandidateMechanism &m, const SelectionCriteria &criteria);
    // Ours: the paper's filter over the whole motion, and defect-free.
    bool meets_all_criteria(const CandidateMechanism &m, const SelectionCriteria &criteria);
  } // namespace burmester
} // namespace compliant
