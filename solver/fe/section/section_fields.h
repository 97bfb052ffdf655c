// Fields of a cross-section for ParaView (VTU): warping about the centroid and about the shear
// centre, shear stress per unit twist rate, shear stress for the torque and its magnitude. The
// file appears under its final name only when complete.
#pragma once

#include "section/section_properties.h"
#include "section/warping_problem.h"

#include <string>

namespace compliant::section
{
  // Returns the path of the .vtu file. shear_modulus and torque in the case's units.
  std::string write_section_fields(const WarpingProblem &problem, const SectionProperties &section,
                                   double shear_modulus, double torque,
                                   const std::string &directory);
} // namespace compliant::section
