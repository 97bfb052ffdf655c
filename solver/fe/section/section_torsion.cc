// section_torsion: Saint-Venant torsion of a cross-section from gmsh. A case file in; area
// moments, torsion constant, shear centre, warping constant, peak shear stress, closed-form
// comparison, fields (VTU) and a JSON summary out.
//   section_torsion cases/section/<case>.prm [--set "Section/Name=value"]... [--check]
#include <deal.II/base/timer.h>

#include <closed_forms/registry.h>

#include "input/case_file.h"
#include "output/summary.h"
#include "quantities/comparison.h"
#include "section/boundary_corners.h"
#include "section/section_case.h"
#include "section/section_fields.h"
#include "section/section_properties.h"
#include "section/warping_problem.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

using namespace compliant;
using namespace compliant::section;

namespace
{
  // Concave kinks smaller than this are facets of a curved boundary, not modelled corners.
  constexpr double facet_kink_degrees = 5.0;
  // A corner of at least this interior angle is a modelled sharp corner (a 90-degree fillet
  // drawn with 4 facets or more turns by at most 22.5 degrees per vertex).
  constexpr double sharp_corner_degrees = 210.0;
  // A peak within this many cell sizes of a concave vertex is taken to be caused by it.
  constexpr double corner_reach_in_cells = 2.0;

  void print_help(const dealii::ParameterHandler &prm, bool with_case)
  {
    std::cout
      << "Usage: section_torsion CASE.prm [--set \"Section/Name=value\"]... [--check]\n"
         "  --help    this text; with a case file, its parameters and current values\n"
         "  --check   read and validate the case and the mesh, then stop (no output)\n"
         "  --set     override any parameter, e.g. --set \"Geometry/Parameters/a=5\"\n\n"
         "Saint-Venant torsion: warping function omega with Laplace(omega) = 0, d omega/dn = "
         "y n_x - x n_y,\nzero mean, about the centroid; J = I_p + int (x omega_y - y omega_x) dA, "
         "Gamma = int omega_S^2 dA\nabout Trefftz's shear centre, tau = G theta' (omega_x - y, "
         "omega_y + x).\n\n"
      << (with_case ? "Parameters of this case (value, default and documentation):\n" :
                      "Parameters (default and documentation):\n");
    prm.print_parameters(std::cout, dealii::ParameterHandler::Text);
    std::cout << "\nGeometry/Parameters come from the .geo file's DefineConstant[... Name "
                 "\"Parameters/...\"] entries;\ngive a case file to list them.\n\n"
                 "Closed forms for Comparison/Checks:\n"
              << closed_forms::documentation();
  }

  std::string format_point(const dealii::Point<2> &p)
  {
    std::ostringstream s;
    s << "(" << p[0] << ", " << p[1] << ")";
    return s.str();
  }

  std::string degrees(const double radians)
  {
    return std::to_string(int(std::round(radians * 180 / M_PI)));
  }

  bool is_sharp(const BoundaryCorner &c)
  {
    return c.interior_angle >= sharp_corner_degrees * M_PI / 180;
  }

  // Warnings on the peak stress: concave vertices make it mesh-dependent.
  std::vector<std::string> stress_warnings(const std::vector<BoundaryCorner> &concave,
                                           const SectionProperties           &section)
  {
    std::vector<std::string> warnings;
    const BoundaryCorner    *nearest = nullptr;
    for (const auto &c : concave)
      if (c.location.distance(section.max_shear_location) <= corner_reach_in_cells * c.cell_size &&
          (!nearest || c.location.distance(section.max_shear_location) <
                         nearest->location.distance(section.max_shear_location)))
        nearest = &c;
    const auto n_sharp = std::count_if(concave.begin(), concave.end(), is_sharp);
    if (nearest && is_sharp(*nearest))
      warnings.push_back(
        "the peak shear stress is at the reentrant corner " + format_point(nearest->location) +
        " (interior angle " + degrees(nearest->interior_angle) +
        " degrees), where the exact stress is infinite: the value grows with mesh refinement. "
        "Round the corner (fillet) for a meaningful peak; J and Gamma stay finite (they converge, "
        "more slowly).");
    else if (nearest)
      warnings.push_back(
        "the peak shear stress is at a concave vertex of a faceted curve " +
        format_point(nearest->location) + " (interior angle " +
        degrees(nearest->interior_angle) +
        " degrees): check it with a finer gmsh mesh of that curve (Global refinements keep the "
        "facets).");
    else if (n_sharp > 0)
      warnings.push_back("the section has " + std::to_string(n_sharp) +
                         " reentrant corner(s) with infinite shear stress; the reported peak lies "
                         "elsewhere, but local stresses near them are mesh-dependent");
    return warnings;
  }

  int run(const SectionCase &c, bool check_only)
  {
    dealii::Timer        timer;
    const MeshedGeometry geometry = [&] {
      try
        {
          return mesh_geometry(c.mesh_file, c.geometry_parameters);
        }
      catch (const std::exception &e)
        {
          throw InputError("case file '" + c.case_file + "', Geometry/Mesh file: " + e.what());
        }
    }();
    WarpingProblem problem(geometry, c.element_degree, c.global_refinements, c.mesh_file);
    std::cout << "Mesh: " << problem.triangulation.n_active_cells() << " cells ("
              << (problem.triangulation.all_reference_cells_are_simplex() ? "triangles" :
                                                                           "quadrilaterals")
              << "), degree " << c.element_degree << std::endl;
    if (check_only)
      {
        std::cout << "Case '" << c.case_file << "' is valid." << std::endl;
        return 0;
      }

    problem.solve();
    const SectionProperties s = compute_section_properties(problem);
    const auto concave  = reentrant_corners(problem.triangulation, facet_kink_degrees * M_PI / 180);
    const auto warnings = stress_warnings(concave, s);

    RunSummary summary;
    summary.case_file  = c.case_file;
    summary.parameters = c.geometry_parameters;
    summary.settings   = {{"mesh_file", c.mesh_file},
                        {"element_degree", std::to_string(c.element_degree)},
                        {"cell_type", problem.triangulation.all_reference_cells_are_simplex() ?
                                        "simplex" : "hypercube"}};
    for (unsigned int i = 0; i < warnings.size(); ++i)
      summary.settings["warning_" + std::to_string(i + 1)] = warnings[i];

    auto &q                              = summary.quantities;
    q["area"]                            = s.area;
    q["centroid_x"]                      = s.centroid[0];
    q["centroid_y"]                      = s.centroid[1];
    q["second_moment_about_x"]           = s.second_moment_about_x;
    q["second_moment_about_y"]           = s.second_moment_about_y;
    q["product_moment_xy"]               = s.product_moment_xy;
    q["polar_moment"]                    = s.polar_moment;
    q["torsion_constant"]                = s.torsion_constant;
    q["shear_centre_x"]                  = s.shear_centre[0];
    q["shear_centre_y"]                  = s.shear_centre[1];
    q["warping_constant"]                = s.warping_constant;
    q["warping_constant_about_centroid"] = s.warping_constant_about_centroid;
    q["shear_modulus"]                   = c.shear_modulus;
    q["torque"]                          = c.torque;
    q["torsional_rigidity"]              = c.shear_modulus * s.torsion_constant;
    q["twist_rate"]                      = c.torque / (c.shear_modulus * s.torsion_constant);
    q["max_shear_stress_per_unit_twist"] = c.shear_modulus * s.max_shear_factor;
    q["max_shear_stress"]                = std::abs(c.torque) * s.max_shear_factor / s.torsion_constant;
    q["max_shear_stress_x"]              = s.max_shear_location[0];
    q["max_shear_stress_y"]              = s.max_shear_location[1];
    q["reentrant_corners"] = std::count_if(concave.begin(), concave.end(), is_sharp);
    q["n_cells"]                         = problem.triangulation.n_active_cells();
    q["n_dofs"]                          = problem.dof_handler.n_dofs();

    auto variables = c.geometry_parameters;
    variables["G"]  = c.shear_modulus;
    variables["E"]  = c.youngs_modulus;
    variables["nu"] = c.poissons_ratio;
    variables["T"]  = c.torque;
    try
      {
        add_derived_quantities(c.derived, summary.quantities, variables);
        summary.comparisons = run_checks(parse_checks(c.checks), summary.quantities, variables);
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + c.case_file + "': " + e.what());
      }

    std::filesystem::create_directories(c.output_directory);
    if (c.write_fields)
      write_section_fields(problem, s, c.shear_modulus, c.torque, c.output_directory);
    q["time_total"] = timer.wall_time();
    write_summary(summary, c.output_directory + "/summary.json");
    std::cout << "\n" << format_table(summary);
    for (const auto &w : warnings)
      std::cout << "WARNING: " << w << "\n";
    std::cout << "\nResults in " << c.output_directory << "/ (summary.json"
              << (c.write_fields ? ", section.vtu" : "") << ")" << std::endl;
    return 0;
  }
} // namespace

int main(int argc, char **argv)
{
  try
    {
      const CommandLine        command_line = parse_command_line(argc, argv);
      dealii::ParameterHandler prm;
      const SectionCase        c = read_section_case(command_line, prm);
      if (command_line.help)
        {
          print_help(prm, !c.case_file.empty());
          return 0;
        }
      if (c.case_file.empty())
        throw InputError("no case file given (try --help)");
      try
        {
          return run(c, command_line.check);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError("case file '" + c.case_file + "': " + e.what());
        }
    }
  catch (const InputError &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "error: " << e.what() << std::endl;
      return 1;
    }
}
