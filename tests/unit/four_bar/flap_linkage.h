// Linkages shared by the four-bar tests.
#pragma once

#include <mechanisms/four_bar/link_lengths.h>

namespace compliant
{
  namespace four_bar
  {
    namespace testing
    {
      // The flap paper's Table 1 (metres): a change-point linkage, 10 + 65 = 60 + 15.
      inline LinkLengths flap_linkage()
      {
        return {0.060, 0.010, 0.065, 0.015};
      }

      // Norton, Design of Machinery, Example 4-1 (ground 6, crank 2, coupler 7, rocker 9):
      // a Grashof crank-rocker with no singular position.
      inline LinkLengths norton_crank_rocker()
      {
        return {6., 2., 7., 9.};
      }

      constexpr double deg = M_PI / 180.;
    } // namespace testing
  }   // namespace four_bar
} // namespace compliant
