// The units of a case ('Geometry/Unit system'), parsed once from the case file. Library materials
// are stored in SI and converted to them (materials/material.h).
#pragma once

#include <stdexcept>
#include <string>

namespace compliant
{
  enum class UnitSystem
  {
    si,      // m, N, Pa, kg/m^3
    mm_n_mpa // mm, N, MPa, t/mm^3
  };

  inline std::string to_string(const UnitSystem units)
  {
    return units == UnitSystem::si ? "SI" : "mm-N-MPa";
  }

  // "SI" or "mm-N-MPa"; std::invalid_argument for anything else.
  inline UnitSystem unit_system_from_string(const std::string &text)
  {
    if (text == "SI")
      return UnitSystem::si;
    if (text == "mm-N-MPa")
      return UnitSystem::mm_n_mpa;
    throw std::invalid_argument("Unit system: expected SI or mm-N-MPa, got '" + text + "'");
  }
} // namespace compliant
