#include "section/section_case.h"

#include "input/spec_list.h"

#include <cmath>
#include <fstream>

namespace compliant::section
{
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  void declare_section_parameters(ParameterHandler                     &prm,
                                  const std::vector<GeometryParameter> &geometry_parameters)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Mesh file", "", Patterns::Anything(),
                        "A 2D cross-section: parametric gmsh .geo file (meshed at run time) or a "
                        "ready .msh file, all triangles or all quadrilaterals. Relative paths are "
                        "looked up next to the case file, then in meshes/.");
      prm.enter_subsection("Parameters");
      for (const auto &p : geometry_parameters)
        prm.declare_entry(p.name, dealii::Utilities::to_string(p.value, 17), Patterns::Double(),
                          p.help.empty() ? "Geometry parameter of the .geo file." : p.help);
      prm.leave_subsection();
    }
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Element degree", "2", Patterns::Integer(1, 3),
                        "Polynomial degree of the warping function (1 to 3; triangles: 1 or 2).");
      prm.declare_entry("Global refinements", "0", Patterns::Integer(0, 8),
                        "Uniform refinements of the gmsh mesh before solving (new boundary "
                        "vertices lie on the straight edges of the gmsh mesh).");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry("Shear modulus", "0", Patterns::Double(0),
                        "G in the case's stress unit; 0: G = E / (2 (1 + nu)). Units are those of "
                        "the mesh and the torque, e.g. mm, N mm and MPa.");
      prm.declare_entry("Young's modulus", "210000", Patterns::Double(0),
                        "E, used when Shear modulus is 0.");
      prm.declare_entry("Poisson's ratio", "0.3", Patterns::Double(-1, 0.5),
                        "nu, used when Shear modulus is 0.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Load");
    {
      prm.declare_entry("Torque", "1", Patterns::Double(),
                        "Torque T about the bar axis: gives the twist rate T / (G J) and the "
                        "shear stress field.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Quantities");
    {
      prm.declare_entry("Derived", "", Patterns::Anything(),
                        "Quantities computed from others with muparser: "
                        "'beta = torsion_constant / (a * b^3)'. Names of quantities, geometry "
                        "parameters, G, E, nu and T may be used.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Comparison");
    {
      prm.declare_entry("Checks", "", Patterns::Anything(),
                        "Quantities compared with closed forms: "
                        "'torsion_constant ~ torsion_constant(a=a, b=b); warping_constant ~ "
                        "warping_constant(a=a, b=b)'. Arguments are muparser expressions of "
                        "geometry parameters, G, E, nu, T and quantities.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory", "", Patterns::Anything(),
                        "Where results go; empty: results/<case file name>.");
      prm.declare_entry("Fields", "true", Patterns::Bool(),
                        "Write section.vtu: warping about the centroid and about the shear "
                        "centre, shear stress per unit twist rate and for the torque, and its "
                        "magnitude.");
    }
    prm.leave_subsection();
  }

  namespace
  {
    // Applies "A/B/Name=value"; names the override on failure.
    void apply_override(ParameterHandler &prm, const std::string &text, bool ignore_undeclared)
    {
      const auto eq = text.find('=');
      if (eq == std::string::npos)
        throw InputError("--set \"" + text + "\": expected \"Section/Name=value\"");
      auto              parts = split(trim(text.substr(0, eq)), '/');
      const std::string name  = parts.back();
      parts.pop_back();
      unsigned int depth = 0;
      std::string  error;
      try
        {
          for (const auto &section : parts)
            {
              prm.enter_subsection(section);
              ++depth;
            }
          prm.set(name, trim(text.substr(eq + 1)));
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
      if (!error.empty() && !ignore_undeclared)
        throw InputError("--set \"" + text + "\": no such parameter, or value not allowed");
    }

    void parse_file(ParameterHandler &prm, const std::string &file, bool skip_undefined)
    {
      if (!std::ifstream(file).good())
        throw InputError("case file '" + file + "' cannot be opened");
      try
        {
          prm.parse_input(file, "", skip_undefined, true);
        }
      catch (const std::exception &e)
        {
          // deal.II's message carries a banner; the useful part follows "Additional information".
          std::string message = e.what();
          const auto  pos     = message.find("Additional information:");
          if (pos != std::string::npos)
            message = message.substr(pos + 23);
          const auto end = message.find("Stacktrace:");
          throw InputError("case file '" + file + "': " + trim(message.substr(0, end)));
        }
    }
  } // namespace

  SectionCase read_section_case(const CommandLine &command_line, ParameterHandler &prm)
  {
    SectionCase c;
    c.case_file = command_line.case_file;

    std::vector<GeometryParameter> geometry_parameters;
    if (!c.case_file.empty())
      {
        ParameterHandler first_pass;
        declare_section_parameters(first_pass, {});
        parse_file(first_pass, c.case_file, true);
        for (const auto &o : command_line.overrides)
          apply_override(first_pass, o, true);
        first_pass.enter_subsection("Geometry");
        c.mesh_file = resolve_mesh_file(first_pass.get("Mesh file"), c.case_file);
        first_pass.leave_subsection();
        if (c.mesh_file.empty())
          throw InputError("case file '" + c.case_file +
                           "': Geometry/Mesh file is empty; expected a .geo or .msh file");
        try
          {
            geometry_parameters = read_geometry_parameters(c.mesh_file);
          }
        catch (const std::exception &e)
          {
            throw InputError("case file '" + c.case_file + "', Geometry/Mesh file: " + e.what());
          }
      }

    declare_section_parameters(prm, geometry_parameters);
    if (c.case_file.empty())
      return c;
    parse_file(prm, c.case_file, false);
    for (const auto &o : command_line.overrides)
      apply_override(prm, o, false);

    prm.enter_subsection("Geometry");
    prm.enter_subsection("Parameters");
    for (const auto &g : geometry_parameters)
      c.geometry_parameters[g.name] = prm.get_double(g.name);
    prm.leave_subsection();
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    c.element_degree     = prm.get_integer("Element degree");
    c.global_refinements = prm.get_integer("Global refinements");
    prm.leave_subsection();

    prm.enter_subsection("Material");
    c.youngs_modulus = prm.get_double("Young's modulus");
    c.poissons_ratio = prm.get_double("Poisson's ratio");
    c.shear_modulus  = prm.get_double("Shear modulus");
    prm.leave_subsection();
    if (c.shear_modulus == 0)
      {
        if (!(c.youngs_modulus > 0) || !(c.poissons_ratio > -1))
          throw InputError("case file '" + c.case_file +
                           "': Material/Shear modulus is 0, so Material/Young's modulus must be "
                           "positive and Poisson's ratio in (-1, 0.5]");
        c.shear_modulus = c.youngs_modulus / (2 * (1 + c.poissons_ratio));
      }

    prm.enter_subsection("Load");
    c.torque = prm.get_double("Torque");
    prm.leave_subsection();
    if (!std::isfinite(c.torque))
      throw InputError("case file '" + c.case_file + "': Load/Torque must be a finite number");

    prm.enter_subsection("Quantities");
    c.derived = prm.get("Derived");
    prm.leave_subsection();
    prm.enter_subsection("Comparison");
    c.checks = prm.get("Checks");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    c.output_directory = prm.get("Directory");
    c.write_fields     = prm.get_bool("Fields");
    prm.leave_subsection();
    if (c.output_directory.empty())
      {
        auto stem          = c.case_file.substr(c.case_file.rfind('/') + 1);
        stem               = stem.substr(0, stem.rfind('.'));
        c.output_directory = "results/section/" + stem;
      }
    return c;
  }
} // namespace compliant::section
