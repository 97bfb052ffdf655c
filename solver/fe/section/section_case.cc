#include "section/section_case.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

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
      declare_geometry_parameters(prm, geometry_parameters);
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

  SectionCase read_section_case(const CommandLine &command_line, ParameterHandler &prm)
  {
    SectionCase c;
    c.case_file = command_line.case_file;

    const auto parsed = read_parameter_file(command_line, prm, declare_section_parameters);
    if (c.case_file.empty())
      return c;
    c.mesh_file           = parsed.mesh_file;
    c.geometry_parameters = parsed.geometry_parameters;

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
      c.output_directory = default_output_directory(c.case_file, "section/");
    return c;
  }
} // namespace compliant::section
