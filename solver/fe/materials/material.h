// Isotropic linear elastic materials: the library data file and the case's per-body choice.
#pragma once

#include "input/unit_system.h"

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct Material
  {
    std::string name;
    double      youngs_modulus  = 0;
    double      poissons_ratio  = 0;
    double      density         = 0;
    double      yield_strength  = 0;
    std::string source;

    double shear_modulus() const { return youngs_modulus / (2 * (1 + poissons_ratio)); }
    double lame_lambda() const
    {
      return youngs_modulus * poissons_ratio / ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
    }
  };

  // Reads the library (SI units). Throws std::runtime_error naming file and line.
  std::map<std::string, Material> read_material_library(const std::string &file);
  std::string                     default_material_library();

  // Resolves 'body: library_name [, E=..., nu=..., density=..., yield=...]; ...' against the
  // mesh's bodies. '*' applies to every body not named otherwise. Values are converted from SI to
  // the case's unit system. Throws std::invalid_argument naming the entry.
  std::map<int, Material> assign_materials(const std::string                &spec,
                                           const std::map<std::string, int> &bodies,
                                           UnitSystem                        unit_system);

  std::string material_library_documentation();

  // Names usable in Derived and Checks expressions: the geometry parameters, the thickness and
  // E, nu, G of the given material.
  std::map<std::string, double> expression_variables(const std::map<std::string, double> &geometry_parameters,
                                                     const Material &material, double thickness);
} // namespace compliant
