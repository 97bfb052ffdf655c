#include "ladder/paired_model.h"

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "materials/material.h"
#include "input/case_geometry.h"
#include "input/expression.h"
#include "input/spec_list.h"
#include "mesh/mesh_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <utility>
#include <sstream>
#include <stdexcept>

namespace compliant
{
  namespace
  {
    template <int dim>
    double mesh_volume(const MeshedGeometry &geometry)
    {
      dealii::Triangulation<dim> triangulation;
      create_triangulation(triangulation, geometry, 0);
      return dealii::GridTools::volume(triangulation);
    }

    // The part's volume on the unrefined, straight-sided mesh: a 2D area times the thickness.
    double part_volume(const CaseParameters &p, const MeshedGeometry &geometry)
    {
      return geometry.dimension == 3 ? mesh_volume<3>(geometry) : mesh_volume<2>(geometry) * p.thickness;
    }

    // The distinct materials of a case (E, nu), in its unit system.
    std::set<std::pair<double, double>> distinct_materials(const CaseParameters &p, const MeshedGeometry &geometry)
    {
      std::set<std::pair<double, double>> found;
      for (const auto &[id, m] : assign_materials(p.materials, geometry.material_ids, p.unit_system))
        found.insert({m.youngs_modulus, m.poissons_ratio});
      return found;
    }
  } // namespace

  PairedModel read_paired_model(const CaseParameters &primary, const MeshedGeometry &primary_geometry,
                                const std::string &spec, MPI_Comm communicator)
  {
    const std::string where = "case file '" + primary.case_file + "', Target/Paired model";
    const auto        colon = spec.find(':');
    const std::string file  = trim(spec.substr(0, colon));
    if (file.empty())
      throw InputError(where + ": expected 'case.prm[: Section/Entry=expression, ...]', got '" + spec + "'");
    const auto        slash     = primary.case_file.rfind('/');
    const std::string case_dir  = slash == std::string::npos ? "." : primary.case_file.substr(0, slash);
    const std::string path      = file[0] == '/' || std::ifstream(case_dir + "/" + file).fail() ? file :
                                                                                                  case_dir + "/" + file;
    if (std::ifstream(path).fail() || std::filesystem::is_directory(path))
      throw InputError(where + ": cannot read the case file '" + file + "' (looked next to the case and "
                       "in the working directory)");

    // Same-named geometry parameters follow the primary, and so do its --set materials and unit
    // system; then the spec's own entries.
    std::map<std::string, double> variables = primary.geometry_parameters;
    if (primary.dimension == 2)
      variables["thickness"] = primary.thickness;
    CommandLine command_line;
    command_line.case_file = path;
    for (const auto &o : primary.overrides)
      if (o.rfind("Material/Materials=", 0) == 0 || o.rfind("Material/Unit system=", 0) == 0)
        command_line.overrides.push_back(o);
    try
      {
        dealii::ParameterHandler first;
        const auto               plain = read_case(command_line, first);
        for (const auto &[name, value] : plain.geometry_parameters)
          if (primary.geometry_parameters.count(name))
            command_line.overrides.push_back("Geometry/Parameters/" + name + "=" +
                                             round_trip_text(primary.geometry_parameters.at(name)));
      }
    catch (const InputError &e)
      {
        throw InputError(where + " '" + spec + "': " + e.what());
      }
    if (colon != std::string::npos)
      for (const auto &item : split(spec.substr(colon + 1), ','))
        {
          const auto entry = trim(item);
          if (entry.empty())
            continue;
          const auto equals = entry.find('=');
          if (equals == std::string::npos || trim(entry.substr(0, equals)).empty())
            throw InputError(where + ": expected 'Section/Entry=expression', got '" + entry + "'");
          double value;
          try
            {
              value = evaluate_expression(entry.substr(equals + 1), variables, "Target/Paired model");
            }
          catch (const std::invalid_argument &e)
            {
              throw InputError("case file '" + primary.case_file + "': " + e.what());
            }
          command_line.overrides.push_back(trim(entry.substr(0, equals)) + "=" + round_trip_text(value));
        }

    PairedModel paired;
    paired.prm = std::make_unique<dealii::ParameterHandler>();
    try
      {
        paired.parameters = read_case(command_line, *paired.prm);
      }
    catch (const InputError &e)
      {
        // The entries set from the spec look like --set ones to the reader: say where they came from.
        throw InputError(where + " '" + spec + "': " + e.what());
      }
    auto &q           = paired.parameters;
    if (q.reduced_integration)
      throw InputError(where + ": '" + path + "' sets Discretization/Integration = reduced; the model ladder "
                       "compares fully integrated rungs (its finite-strain rungs have no reduced rule)");
    if (q.analysis != "linear static")
      throw InputError(where + ": '" + path + "' runs Analysis = " + q.analysis +
                       "; expected linear static (the ladder climbs linear static cases)");
    if (q.dimension == primary.dimension)
      throw InputError(where + ": '" + path + "' is a " + std::to_string(q.dimension) +
                       "D model like the case itself; expected the " + (primary.dimension == 3 ? "2D" : "3D") +
                       " model of the same part");
    const auto &plane = primary.dimension == 2 ? primary : q;
    if (plane.model != Model::plane_stress)
      throw InputError(where + ": the 2D model ('" + plane.case_file + "') has Model = " + std::string(to_string(plane.model)) +
                       "; expected plane stress (the out-of-plane bound that justifies 2D exists for "
                       "plane stress only)");
    q.output_directory = primary.output_directory;
    q.write_fields     = primary.write_fields;
    q.write_pictures   = primary.write_pictures;
    paired.geometry    = mesh_case_geometry(q, communicator);

    // The two models must describe one part: the same materials, and the same volume up to the
    // chords of coarse curved boundaries. (Loads and supports cannot be compared in general: the
    // case files must give the same ones.)
    try
      {
        if (distinct_materials(primary, primary_geometry) != distinct_materials(q, paired.geometry))
          throw InputError(where + ": '" + path + "' does not describe the same part: its materials "
                           "(Material/Materials, Material/Unit system) differ from the case's; expected "
                           "the same E and nu");
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(where + " '" + spec + "': " + e.what());
      }
    const double v_primary = part_volume(primary, primary_geometry), v_paired = part_volume(q, paired.geometry);
    if (!(std::abs(v_primary - v_paired) <= 0.02 * std::max(v_primary, v_paired)))
      {
        std::ostringstream s;
        s << where << ": '" << path << "' does not describe the same part: volume " << v_paired
          << " (" << (q.dimension == 2 ? "area times Material/Thickness" : "3D mesh") << ") against "
          << v_primary << " of the case (" << (primary.dimension == 2 ? "area times Material/Thickness" : "3D mesh")
          << "); expected equal within 2 % (set the paired entries in the spec, e.g. "
          << (q.dimension == 2 ? "'section.prm: Material/Thickness=W')" : "'part.prm: Geometry/Parameters/W=thickness')");
        throw InputError(s.str());
      }
    return paired;
  }
} // namespace compliant
