#include "input/case_file.h"

#include "input/spec_list.h"

#include <cstdio>
#include <fstream>
#include <cmath>
#include <sstream>

#ifndef COMPLIANT_SOURCE_DIR
#  define COMPLIANT_SOURCE_DIR "."
#endif

namespace compliant
{
  const char *to_string(const Model model)
  {
    return model == Model::three_d ? "3d" : model == Model::plane_strain ? "plane strain" : "plane stress";
  }

  const char *to_string(const Formulation formulation)
  {
    return formulation == Formulation::mixed ? "mixed" : "displacement";
  }

  using dealii::ParameterHandler;

  CommandLine parse_command_line(int argc, char **argv)
  {
    CommandLine cl;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          cl.help = true;
        else if (arg == "--check")
          cl.check = true;
        else if (arg == "--set")
          {
            if (i + 1 >= argc)
              throw InputError("--set needs an argument \"Section/Name=value\"");
            cl.overrides.emplace_back(argv[++i]);
          }
        else if (arg.rfind("--set=", 0) == 0)
          cl.overrides.push_back(arg.substr(6));
        else if (!arg.empty() && arg[0] == '-')
          throw InputError("unknown option '" + arg + "' (known: --help, --check, --set)");
        else if (cl.case_file.empty())
          cl.case_file = arg;
        else
          throw InputError("more than one case file given: '" + cl.case_file + "' and '" + arg +
                           "'");
      }
    return cl;
  }

  std::string default_output_directory(const std::string &case_file, const std::string &prefix)
  {
    auto stem = case_file.substr(case_file.rfind('/') + 1);
    stem      = stem.substr(0, stem.rfind('.'));
    return "results/" + prefix + stem;
  }

  std::string resolve_mesh_file(const std::string &name, const std::string &case_file)
  {
    if (name.empty())
      return "";
    if (name[0] == '/')
      return name;
    const auto        slash    = case_file.rfind('/');
    const std::string case_dir = slash == std::string::npos ? "." : case_file.substr(0, slash);
    for (const std::string &candidate :
         {case_dir + "/" + name, std::string(COMPLIANT_SOURCE_DIR) + "/meshes/" + name, name})
      if (std::ifstream(candidate).good())
        return candidate;
    return case_dir + "/" + name; // reported as missing later
  }

  namespace
  {
    std::string describe_parameter_error(const std::string &what, const std::string &path);

    // gmsh guesses the format of a name it does not know by extension, and a name with a control
    // character (a NUL cuts it short for the C library, not for gmsh) sent it into endless merging:
    // only plain .geo and .msh names go to gmsh. Found by fuzzing the case reader.
    void refuse_unreadable_mesh_name(const std::string &name, const std::string &file)
    {
      for (std::size_t i = 0; i < name.size(); ++i)
        if (static_cast<unsigned char>(name[i]) < 0x20 || name[i] == 0x7f)
          {
            char byte[8];
            std::snprintf(byte, sizeof(byte), "0x%02x", static_cast<unsigned char>(name[i]));
            throw InputError("case file '" + file + "', Geometry/Mesh file: control character " + byte +
                             " at position " + std::to_string(i + 1) + " of the name; expected a .geo, .msh or .inp file name");
          }
      const auto ends_with = [&](const std::string &suffix) {
        return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
      };
      if (!name.empty() && !ends_with(".geo") && !ends_with(".msh") && !ends_with(".inp"))
        throw InputError("case file '" + file + "', Geometry/Mesh file: '" + name +
                         "' is neither a .geo, .msh nor .inp (Abaqus/CalculiX) file");
    }

    // Applies "A/B/Name=value" to the handler; names the override on failure.
    void apply_override(ParameterHandler &prm, const std::string &text, bool ignore_undeclared)
    {
      const auto eq = text.find('=');
      if (eq == std::string::npos)
        throw InputError("--set \"" + text + "\": expected \"Section/Name=value\"");
      const std::string path  = trim(text.substr(0, eq));
      const std::string value = trim(text.substr(eq + 1));
      auto              parts = split(path, '/');
      const std::string name  = parts.back();
      parts.pop_back();
      unsigned int depth = 0;
      try
        {
          for (const auto &section : parts)
            {
              prm.enter_subsection(section);
              ++depth;
            }
          prm.set(name, value);
        }
      catch (const std::exception &e)
        {
          for (; depth > 0; --depth)
            prm.leave_subsection();
          if (ignore_undeclared)
            return;
          throw InputError("--set \"" + text + "\": " + describe_parameter_error(e.what(), path));
        }
      for (; depth > 0; --depth)
        prm.leave_subsection();
    }

    std::string first_lines(const std::string &s)
    {
      // deal.II exceptions carry a long banner; the useful part is the "Additional information".
      const auto pos = s.find("Additional information:");
      std::string out = pos == std::string::npos ? s : s.substr(pos + 23);
      const auto  end = out.find("Stacktrace:");
      if (end != std::string::npos)
        out = out.substr(0, end);
      // one line: the banner wraps its text
      std::string flat;
      for (const char c : trim(out))
        if (c == '\n' || c == '\t' || c == ' ')
          {
            if (!flat.empty() && flat.back() != ' ')
              flat += ' ';
          }
        else
          flat += c;
      return flat;
    }

    // A ParameterHandler failure on "Section/Name" in words: which value is not allowed and what
    // the pattern expects, or that no such parameter exists.
    std::string describe_parameter_error(const std::string &what, const std::string &path)
    {
      const std::string detail = first_lines(what);
      const std::string marker = "The string <", middle = "> does not match the given pattern <";
      const auto        a = detail.find(marker), b = detail.find(middle);
      if (a != std::string::npos && b != std::string::npos && b > a)
        {
          std::string pattern = detail.substr(b + middle.size());
          pattern             = pattern.substr(0, pattern.rfind('>'));
          if (!pattern.empty() && pattern.front() == '[')
            pattern = pattern.substr(1, pattern.rfind(']') - 1);
          return "value '" + detail.substr(a + marker.size(), b - a - marker.size()) +
                 "' is not allowed for " + path + "; expected " + pattern;
        }
      return "no parameter '" + path + "' (" + detail +
             "); give the full \"Section/Name=value\" as --help lists it";
    }

    // deal.II 9.4 does not check a value that starts with '{' against its entry's pattern (found
    // by fuzzing: 'set t = {1' then failed in get_double with a stack dump). No case value
    // starts with a brace, so such a line is refused with its number.
    void refuse_braced_values(const std::string &text, const std::string &file)
    {
      std::istringstream lines(text);
      std::string        line;
      for (unsigned int number = 1; std::getline(lines, line); ++number)
        {
          const std::string content = trim(line);
          if (content.rfind("set ", 0) != 0 && content.rfind("set\t", 0) != 0)
            continue;
          const auto equals = content.find('=');
          if (equals != std::string::npos && trim(content.substr(equals + 1)).rfind('{', 0) == 0)
            throw InputError("case file '" + file + "', line " + std::to_string(number) + ": the value of '" +
                             trim(content.substr(4, equals - 4)) +
                             "' starts with '{'; give the value itself (a number, name or list)");
        }
    }

    void parse_file(ParameterHandler &prm, const std::string &file, bool skip_undefined)
    {
      if (!std::ifstream(file).good())
        throw InputError("case file '" + file + "' cannot be opened");
      try
        {
          // Read as text: a UTF-8 byte-order mark (editors on Windows write one) is dropped,
          // CRLF line endings are fine as they are.
          std::ifstream     in(file, std::ios::binary);
          std::stringstream content;
          content << in.rdbuf();
          std::string text = content.str();
          if (text.rfind("\xEF\xBB\xBF", 0) == 0)
            text.erase(0, 3);
          refuse_braced_values(text, file);
          std::istringstream stream(text);
          prm.parse_input(stream, file, "", skip_undefined);
          prm.assert_that_entries_have_been_set();
        }
      catch (const InputError &)
        {
          throw;
        }
      catch (const std::exception &e)
        {
          throw InputError("case file '" + file + "': " + first_lines(e.what()));
        }
    }

    // Discretization/Integration = reduced is built for the linear static stiffness and the
    // finite-strain residual and tangent (assembled and matrix-free); mass and geometric stiffness
    // keep p + 1.
    void check_reduced_integration(const CaseParameters &p)
    {
      const std::string where = "case file '" + p.case_file + "', Discretization/";
      if (p.reduced_integration && p.analysis != "linear static" && p.analysis != "nonlinear static")
        throw InputError(where + "Integration = reduced: for linear and nonlinear static analyses, not " +
                         p.analysis + " (its mass or geometric stiffness stay fully integrated)");
      if (p.reduced_integration && (p.element_degree < 2 || p.formulation == Formulation::mixed))
        throw InputError(where + "Integration = reduced needs Element degree 2 to 4 and Formulation = "
                         "displacement (one Gauss point per direction leaves a degree-1 cell without "
                         "stiffness)");
      if (p.reduced_integration && !(p.hourglass_stiffness > 0))
        throw InputError(where + "Hourglass stiffness: expected a fraction in (0, 1] with Integration = "
                         "reduced (0 leaves the hourglass modes free), got " + std::to_string(p.hourglass_stiffness));
    }
  } // namespace

  ParsedParameterFile read_parameter_file(const CommandLine      &command_line,
                                          ParameterHandler       &prm,
                                          const ParameterDeclarer &declare)
  {
    const std::string             &file = command_line.case_file;
    std::vector<GeometryParameter> geometry_parameters;
    ParsedParameterFile            parsed;
    if (!file.empty())
      {
        ParameterHandler first_pass;
        declare(first_pass, {});
        parse_file(first_pass, file, true);
        for (const auto &o : command_line.overrides)
          apply_override(first_pass, o, true);
        first_pass.enter_subsection("Geometry");
        const std::string mesh_name = first_pass.get("Mesh file");
        double            seconds   = 0; // the time limit of reading the .geo, where declared
        try
          {
            seconds = first_pass.get_double("Meshing time limit");
          }
        catch (...)
          {
          }
        first_pass.leave_subsection();
        refuse_unreadable_mesh_name(mesh_name, file);
        parsed.mesh_file = resolve_mesh_file(mesh_name, file);
        if (parsed.mesh_file.empty())
          throw InputError("case file '" + file +
                           "': Geometry/Mesh file is empty; expected a .geo or .msh file");
        try
          {
            geometry_parameters = read_geometry_parameters(parsed.mesh_file, seconds);
          }
        catch (const std::exception &e)
          {
            throw InputError("case file '" + file + "', Geometry/Mesh file: " + e.what());
          }
      }
    declare(prm, geometry_parameters);
    if (file.empty())
      return parsed;
    parse_file(prm, file, false);
    for (const auto &o : command_line.overrides)
      apply_override(prm, o, false);
    prm.enter_subsection("Geometry");
    prm.enter_subsection("Parameters");
    for (const auto &g : geometry_parameters)
      parsed.geometry_parameters[g.name] = prm.get_double(g.name);
    prm.leave_subsection();
    prm.leave_subsection();
    return parsed;
  }

  CaseParameters read_case(const CommandLine &command_line, ParameterHandler &prm)
  {
    CaseParameters p;
    p.case_file       = command_line.case_file;
    p.overrides       = command_line.overrides;
    const auto parsed = read_parameter_file(command_line, prm, declare_case_parameters);
    if (p.case_file.empty())
      return p;
    p.mesh_file           = parsed.mesh_file;
    p.geometry_parameters = parsed.geometry_parameters;
    p.analysis            = prm.get("Analysis");
    prm.enter_subsection("Geometry");
    try
      {
        p.imperfection = parse_imperfection(prm.get("Imperfection"));
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError("case file '" + p.case_file + "', Geometry/Imperfection: " + e.what());
      }
    p.maximum_cells      = static_cast<std::uint64_t>(prm.get_integer("Maximum cells"));
    p.meshing_time_limit = prm.get_double("Meshing time limit");
    prm.leave_subsection();
    if (!p.imperfection.empty() && p.analysis != "nonlinear static")
      throw InputError("case file '" + p.case_file + "', Geometry/Imperfection: an imperfection shapes the "
                       "path of a nonlinear static analysis, not a " + p.analysis + " analysis");

    const std::string model = prm.get("Model");
    p.model     = model == "3d" ? Model::three_d : model == "plane strain" ? Model::plane_strain : Model::plane_stress;
    p.dimension = p.model == Model::three_d ? 3 : 2;

    prm.enter_subsection("Discretization");
    p.element_degree     = prm.get_integer("Element degree");
    p.global_refinements = prm.get_integer("Global refinements");
    p.mesh_partition     = partition_request_from_string(prm.get("Mesh partition"));
    p.curved_boundaries  = prm.get_bool("Curved boundaries");
    p.curved_mapping_degree = prm.get_integer("Curved mapping degree");
    p.formulation        = prm.get("Formulation") == "mixed" ? Formulation::mixed : Formulation::displacement;
    p.reduced_integration = prm.get("Integration") == "reduced";
    p.hourglass_stiffness = prm.get_double("Hourglass stiffness");
    prm.leave_subsection();
    check_reduced_integration(p);

    prm.enter_subsection("Material");
    p.thickness   = prm.get_double("Thickness");
    if (!(p.thickness > 0) || !std::isfinite(p.thickness))
      throw InputError("case file '" + p.case_file + "', Material/Thickness: expected a positive "
                       "number (the out-of-plane thickness of a 2D model), got " +
                       prm.get("Thickness"));
    p.unit_system = unit_system_from_string(prm.get("Unit system"));
    p.materials   = prm.get("Materials");
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    p.clamped      = prm.get("Clamped");
    p.displacement = prm.get("Displacement");
    p.rotation     = prm.get("Rotation");
    p.rigid        = prm.get("Rigid");
    prm.leave_subsection();
    if (!trim(p.rigid).empty() && p.analysis != "linear static" && p.analysis != "nonlinear static" &&
        p.analysis != "buckling")
      throw InputError("case file '" + p.case_file + "', Boundary conditions/Rigid: rigid "
                       "boundaries are available in linear static, nonlinear static and buckling "
                       "analyses, not in " + p.analysis);

    prm.enter_subsection("Loads");
    p.traction    = prm.get("Traction");
    p.total_force = prm.get("Total force");
    p.pressure    = prm.get("Pressure");
    p.body_force  = prm.get("Body force");
    p.gravity     = prm.get("Gravity");
    prm.leave_subsection();

    prm.enter_subsection("Linear solver");
    p.solver_method         = solver_method_from_string(prm.get("Method"));
    p.solver_tolerance      = prm.get_double("Relative tolerance");
    p.solver_max_iterations = prm.get_integer("Maximum iterations");
    p.petsc_options         = prm.get("PETSc options");
    p.long_edge_coarse_space = prm.get("Coarse space") == "auto";
    prm.leave_subsection();

    prm.enter_subsection("Quantities");
    p.points             = prm.get("Points");
    p.reactions          = prm.get("Reactions");
    p.mean_displacements = prm.get("Mean displacements");
    p.rotations          = prm.get("Rotations");
    p.derived            = prm.get("Derived");
    p.region_maxima      = prm.get("Region maxima");
    p.stress_points      = prm.get("Stress points");
    p.error_estimates    = prm.get_bool("Error estimates");
    if (p.error_estimates && p.analysis != "linear static" && p.analysis != "modal" && p.analysis != "nonlinear static")
      throw InputError("case file '" + p.case_file + "', Quantities/Error estimates: estimates are made for "
                       "linear static, nonlinear static and modal analyses, not a " + p.analysis + " analysis");
    prm.leave_subsection();

    prm.enter_subsection("Comparison");
    p.checks = prm.get("Checks");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    p.output_directory = prm.get("Directory");
    p.write_fields     = prm.get_bool("Fields");
    p.write_pictures   = prm.get_bool("Pictures");
    prm.leave_subsection();
    if (p.output_directory.empty())
      p.output_directory = default_output_directory(p.case_file);
    return p;
  }
} // namespace compliant
