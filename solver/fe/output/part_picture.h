// The picture of a deformed part as SVG (vector, text as text, shown by any browser and inlined
// in report.html): sub-cell polygons coloured in bands by their value, a colour bar, the peak
// marked with its value and place, the undeformed part behind in grey, the deformation's scale
// printed. 3D: the outer surface in two views (one from the side of the peak, one from the
// opposite side), hidden faces culled and the rest painted back to front with flat shading.
#pragma once

#include "output/picture_geometry.h"

#include <string>

namespace compliant
{
  // The factor displacements are drawn with: 1 (true scale) unless the largest displacement is
  // under 2 % of the part's size, then a round number (1, 2 or 5 x 10^k) that makes it about 10 %;
  // for modes (labels.mode_amplitude > 0) that fraction exactly.
  double deformation_scale(const PictureGeometry &geometry, const PictureLabels &labels);

  std::string draw_part(const PictureGeometry &geometry, const PictureLabels &labels);
} // namespace compliant
