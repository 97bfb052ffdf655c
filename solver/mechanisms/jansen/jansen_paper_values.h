// Numbers printed by the seed paper (I. A. Kartal, K. Kavlak, "Strandbeest
// Mekanizmasinin Kinematik ve Mukavemet Analizi", section III) at its
// ground-contact pose, omega2 = 10 rad/s constant. Kept only to be compared
// with: nothing in this library computes from them except the "paper's
// equations with the paper's angles" check of the report.
#pragma once

#include <mechanisms/jansen/jansen_position_analysis.h>
#include <mechanisms/jansen/jansen_quantities.h>

namespace compliant
{
  namespace jansen
  {
    struct PrintedValue
    {
      double value    = 0.;
      int    decimals = 0; // digits after the decimal point as printed
    };

    struct PaperKinematics
    {
      double                                  omega2 = 0.; // rad/s
      std::array<PrintedValue, n_quantities> values{};
    };

    PaperKinematics paper_ground_contact_kinematics();

    // The paper's printed link angles (radians) as a LinkAngles set, with
    // theta1 = 11.6 deg.
    LinkAngles paper_printed_angles();
  } // namespace jansen
} // namespace compliant
