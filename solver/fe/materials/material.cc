#include "materials/material.h"

#include "input/spec_list.h"

#include <fstream>
#include <sstream>
#include <stdexcept>

#ifndef COMPLIANT_SOURCE_DIR
#  define COMPLIANT_SOURCE_DIR "."
#endif

namespace compliant
{
  std::string default_material_library()
  {
    return std::string(COMPLIANT_SOURCE_DIR) + "/solver/fe/materials/library.dat";
  }

  std::map<std::string, Material> read_material_library(const std::string &file)
  {
    std::ifstream in(file);
    if (!in)
      throw std::runtime_error("material library '" + file + "' cannot be opened");
    std::map<std::string, Material> library;
    std::string                     line;
    for (unsigned int line_number = 1; std::getline(in, line); ++line_number)
      {
        if (trim(line).empty() || trim(line)[0] == '#')
          continue;
        std::istringstream s(line);
        Material           m;
        if (!(s >> m.name >> m.youngs_modulus >> m.poissons_ratio >> m.density >> m.yield_strength))
          throw std::runtime_error(file + ":" + std::to_string(line_number) +
                                   ": expected 'name E nu density yield source'");
        std::getline(s, m.source);
        m.source          = trim(m.source);
        library[m.name] = m;
      }
    return library;
  }

  namespace
  {
    Material to_unit_system(Material m, const UnitSystem unit_system)
    {
      if (unit_system == UnitSystem::mm_n_mpa)
        {
          m.youngs_modulus *= 1e-6; // Pa -> MPa
          m.yield_strength *= 1e-6;
          m.density *= 1e-12; // kg/m^3 -> t/mm^3
        }
      return m;
    }
  } // namespace

  std::map<int, Material> assign_materials(const std::string                &spec,
                                           const std::map<std::string, int> &bodies,
                                           const UnitSystem                  unit_system)
  {
    const std::string where   = "Material/Materials";
    const auto        library = read_material_library(default_material_library());
    std::map<std::string, Material> by_body;
    for (const auto &item : parse_spec_list(spec, where))
      {
        if (item.name != "*" && bodies.count(item.name) == 0)
          {
            std::string known;
            for (const auto &b : bodies)
              known += " '" + b.first + "'";
            throw std::invalid_argument(where + ": unknown body '" + item.name +
                                        "'; the mesh has:" + known);
          }
        Material m;
        bool     have_base = false;
        for (const auto &f : item.fields)
          if (f.key.empty())
            {
              const auto it = library.find(f.value);
              if (it == library.end())
                {
                  std::string known;
                  for (const auto &l : library)
                    known += " " + l.first;
                  throw std::invalid_argument(where + ": unknown material '" + f.value +
                                              "' for '" + item.name + "'; library has:" + known);
                }
              m         = to_unit_system(it->second, unit_system);
              have_base = true;
            }
        for (const auto &f : item.fields)
          {
            if (f.key.empty())
              continue;
            const auto v = parse_numbers(f.value, where + " (" + item.name + ", " + f.key + ")");
            if (v.size() != 1)
              throw std::invalid_argument(where + ": '" + f.key + "' of '" + item.name +
                                          "' expects one number");
            if (f.key == "E")
              m.youngs_modulus = v[0];
            else if (f.key == "nu")
              m.poissons_ratio = v[0];
            else if (f.key == "density")
              m.density = v[0];
            else if (f.key == "yield")
              m.yield_strength = v[0];
            else
              throw std::invalid_argument(where + ": unknown property '" + f.key + "' for '" +
                                          item.name + "'; expected E, nu, density or yield");
          }
        if (!have_base)
          m.name = "custom";
        if (!(m.youngs_modulus > 0) || !(m.poissons_ratio > -1 && m.poissons_ratio < 0.5))
          throw std::invalid_argument(where + ": '" + item.name +
                                      "' needs E > 0 and -1 < nu < 0.5 (got E=" +
                                      std::to_string(m.youngs_modulus) +
                                      ", nu=" + std::to_string(m.poissons_ratio) + ")");
        if (!(m.density >= 0) || !(m.yield_strength >= 0))
          throw std::invalid_argument(where + ": '" + item.name +
                                      "' needs density >= 0 and yield >= 0 (got density=" +
                                      std::to_string(m.density) + ", yield=" +
                                      std::to_string(m.yield_strength) + ")");
        by_body[item.name] = m;
      }

    std::map<int, Material> result;
    for (const auto &[name, id] : bodies)
      {
        if (by_body.count(name))
          result[id] = by_body[name];
        else if (by_body.count("*"))
          result[id] = by_body["*"];
        else
          throw std::invalid_argument(where + ": body '" + name +
                                      "' has no material (name it or use '*')");
      }
    return result;
  }

  std::map<std::string, double> expression_variables(const std::map<std::string, double> &geometry_parameters,
                                                     const Material &material, const double thickness)
  {
    auto variables         = geometry_parameters;
    variables["thickness"] = thickness;
    variables["E"]         = material.youngs_modulus;
    variables["nu"]        = material.poissons_ratio;
    variables["G"]         = material.shear_modulus();
    return variables;
  }

  std::string material_library_documentation()
  {
    std::ostringstream out;
    out << "Material library (" << default_material_library() << ", SI units):\n";
    for (const auto &[name, m] : read_material_library(default_material_library()))
      out << "  " << name << ": E=" << m.youngs_modulus << " nu=" << m.poissons_ratio
          << " density=" << m.density << " yield=" << m.yield_strength << "  [" << m.source
          << "]\n";
    return out.str();
  }
} // namespace compliant
