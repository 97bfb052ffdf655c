// The look shared by every picture and chart: the banded rainbow colour scale engineers know from
// ANSYS and Abaqus contour plots, number formatting and text escaping for SVG and HTML.
#pragma once

#include <string>

namespace compliant
{
  constexpr unsigned int colour_bands = 12;

  // Red, green, blue in 0-1 of the band holding t (0 = lowest, 1 = highest value; clamped).
  void band_colour(double t, double &r, double &g, double &b);

  // "#rrggbb" of r, g, b in 0-1, each multiplied by shade.
  std::string hex_colour(double r, double g, double b, double shade = 1.0);

  // A number as engineers read it: 4 significant digits, no trailing zeros.
  std::string short_number(double value, int digits = 4);

  // &, <, >, " escaped for XML/HTML text and attributes.
  std::string escape_xml(const std::string &text);
} // namespace compliant
