#include "output/svg_style.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace compliant
{
  void band_colour(const double t, double &r, double &g, double &b)
  {
    // Band centre on a blue - cyan - green - yellow - red ramp.
    const double clamped = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
    const auto   band    = std::min<unsigned int>(colour_bands - 1, clamped * colour_bands);
    const double s       = (band + 0.5) / colour_bands * 4.0; // 0-4 over the four ramps
    r = std::clamp(s - 2.0, 0.0, 1.0);
    g = s < 1 ? s : (s < 3 ? 1.0 : 4.0 - s);
    b = std::clamp(2.0 - s, 0.0, 1.0);
  }

  std::string hex_colour(const double r, const double g, const double b, const double shade)
  {
    const auto byte = [&](double v) {
      return static_cast<int>(std::lround(std::clamp(v * shade, 0.0, 1.0) * 255));
    };
    char text[8];
    std::snprintf(text, sizeof(text), "#%02x%02x%02x", byte(r), byte(g), byte(b));
    return text;
  }

  std::string short_number(const double value, const int digits)
  {
    if (!std::isfinite(value))
      return "n/a";
    char text[32];
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    return text;
  }

  std::string escape_xml(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      switch (c)
        {
          case '&': out += "&amp;"; break;
          case '<': out += "&lt;"; break;
          case '>': out += "&gt;"; break;
          case '"': out += "&quot;"; break;
          default: out += c;
        }
    return out;
  }
} // namespace compliant
