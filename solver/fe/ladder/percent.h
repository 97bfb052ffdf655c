// A fraction printed as a percentage with two significant digits ("0.25 %"), as the ladder reports.
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

namespace compliant
{
  inline std::string percent(double fraction)
  {
    std::ostringstream s;
    s << std::setprecision(2) << 100 * fraction << " %";
    return s.str();
  }
} // namespace compliant
