#include "input/imperfection_spec.h"

#include "text/text_utilities.h"

#include <cmath>
#include <set>
#include <stdexcept>

namespace compliant
{
  std::vector<ImperfectionMode> parse_imperfection(const std::string &text)
  {
    std::vector<ImperfectionMode> modes;
    if (text::trim(text).empty())
      return modes;
    const std::string expected = "expected '<mode>: <amplitude>[, <mode>: <amplitude> ...]' (a buckling mode "
                                 "number from 1 and the largest displacement component it adds to the "
                                 "geometry, in the case's length unit), got '" + text + "'";
    std::set<unsigned int> seen;
    for (const auto &entry : text::split_trimmed(text, ','))
      {
        const auto parts = text::split_trimmed(entry, ':');
        if (parts.size() != 2 || parts[0].empty() || parts[1].empty())
          throw std::invalid_argument(expected);
        std::size_t used_mode = 0, used_amplitude = 0;
        long        mode      = 0;
        double      amplitude = 0;
        try
          {
            mode      = std::stol(parts[0], &used_mode);
            amplitude = std::stod(parts[1], &used_amplitude);
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument(expected);
          }
        if (used_mode != parts[0].size() || used_amplitude != parts[1].size())
          throw std::invalid_argument(expected);
        if (mode < 1 || mode > 200)
          throw std::invalid_argument("mode " + parts[0] + " is not a buckling mode number (1 to 200); " + expected);
        if (!std::isfinite(amplitude) || amplitude == 0)
          throw std::invalid_argument("amplitude " + parts[1] + " of mode " + parts[0] +
                                      " must be a finite non-zero length; " + expected);
        if (!seen.insert(static_cast<unsigned int>(mode)).second)
          throw std::invalid_argument("mode " + parts[0] + " is given twice; " + expected);
        modes.push_back({static_cast<unsigned int>(mode), amplitude});
      }
    return modes;
  }
} // namespace compliant
