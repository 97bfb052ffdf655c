#include "input/case_file.h"

#include "input/analysis_declarations.h"
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
  namespace Patterns = dealii::Patterns;

  void declare_case_parameters(ParameterHandler                     &prm,
                               const std::vector<GeometryParameter> &geometry_parameters)
  {
    prm.declare_entry("Model", "plane stress",
                      Patterns::Selection("plane stress|plane strain|3d"),
                      "Kinematic model: 2D plane stress (uses Material/Thickness), 2D plane "
                      "strain, or 3D solid. Must match the dimension of the mesh.");
    std::string names, documentation;
    if (registered_analyses().empty())
      throw std::logic_error("no analysis registered before the case was read");
    for (const auto &a : registered_analyses())
      {
        names += (names.empty() ? "" : "|") + a.name;
        documentation += " '" + a.name + "': " + a.documentation + ".";
      }
    prm.declare_entry("Analysis", "linear static", Patterns::Selection(names),
                      "Kind of analysis." + documentation);
    for (const auto &a : registered_analyses())
      a.declare_parameters(prm);

    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Mesh file", "",
                        Patterns::Anything(),
                        "A parametric gmsh .geo file (meshed at run time), a ready .msh file, or an "
                        "Abaqus/CalculiX .inp mesh (element and node sets and surfaces are the "
                        "group names; see README, Geometry). "
                        "Relative paths are looked up next to the case file, then in meshes/.");
      prm.declare_entry("Imperfection", "", Patterns::Anything(),
                        "Nonlinear static analyses: the geometry shifted by buckling mode shapes before "
                        "the run, '<mode>: <amplitude>[, <mode>: <amplitude> ...]' (e.g. '1: 0.01'). "
                        "The modes are those of Analysis = buckling on the perfect geometry under the "
                        "case's loads (settings from the Buckling subsection), each scaled so that its "
                        "largest displacement component is the amplitude (a length, any sign; where a "
                        "positive and a negative component are equally large, as in antisymmetric "
                        "modes, the one at the smallest x, then y, then z, takes the amplitude's sign). "
                        "A path that would meet a bifurcation then follows the buckled branch. Empty: "
                        "the perfect geometry.");
      prm.enter_subsection("Parameters");
      for (const auto &p : geometry_parameters)
        prm.declare_entry(p.name, round_trip_text(p.value), Patterns::Double(),
                          p.help.empty() ? "Geometry parameter of the .geo file." : p.help);
      prm.leave_subsection();
    }
    prm.leave_subsection();

    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Element degree", "2", Patterns::Integer(1, 3),
                        "Polynomial degree of the displacement elements (1 to 3).");
      prm.declare_entry("Global refinements", "0", Patterns::Integer(0, 8),
                        "Uniform refinements of the gmsh mesh before solving.");
      prm.declare_entry("Formulation", "displacement", Patterns::Selection("displacement|mixed"),
                        "Linear static and modal analyses. mixed: displacement Q_k with a discontinuous "
                        "pressure P_(k-1) (Q2-P1 at degree 2), free of volumetric locking for "
                        "nearly incompressible materials (printed TPU, nu near 0.5); plane strain "
                        "and 3D, quadrilaterals/hexahedra, degree 2 or 3, solved by MUMPS. "
                        "Finite strain has its own Finite strain/Formulation.");
      prm.declare_entry("Curved boundaries", "true", Patterns::Bool(),
                        "true: boundaries the gmsh geometry draws as circles (2D) or cylinders "
                        "and spheres (3D) stay on that shape: refinement puts new vertices on it "
                        "and the cells touching it are mapped with the element degree "
                        "(isoparametric), so quadratic elements keep their order on holes and "
                        "notches. Other curved shapes (splines, ellipses) and .msh meshes are "
                        "straight-sided, as the log says. false: every cell straight-sided.");
      prm.declare_entry("Mesh partition", "auto", Patterns::Selection("auto|shared|distributed"),
                        "How the mesh is spread over MPI ranks. shared: every rank holds the "
                        "whole mesh and owns a METIS part. distributed: each rank holds only its "
                        "part (read and cut on rank 0), so the memory per rank falls as ranks "
                        "grow; static analyses only. auto: distributed from 2e5 estimated DoFs "
                        "on more than one rank where the analysis allows it, else shared.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Material");
    {
      prm.declare_entry("Thickness", "1", Patterns::Double(0),
                        "Out-of-plane thickness of 2D models; forces and energies are totals "
                        "over this thickness.");
      prm.declare_entry("Unit system", "SI", Patterns::Selection("SI|mm-N-MPa"),
                        "Units of the case. Library materials are stored in SI and converted: "
                        "mm-N-MPa gives E in MPa, density in t/mm^3.");
      prm.declare_entry("Materials", "*: steel", Patterns::Anything(),
                        "Material of each physical body: 'name: library_material [, E=..., "
                        "nu=..., density=..., yield=...]; ...'. '*' means every body. Library: "
                        "see the materials table in --help.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry("Clamped", "", Patterns::Anything(),
                        "Boundaries with all displacement components zero: 'left, right'.");
      prm.declare_entry("Displacement", "", Patterns::Anything(),
                        "Prescribed displacement per component: 'right: y=0.1; top: x=0, z=0'. "
                        "Components not named stay free. A value may be an expression of x, y, z, e.g. "
                        "'outer: x=1e-3*(x+y/2), y=1e-3*(y+x/2)'.");
      prm.declare_entry("Rotation", "", Patterns::Anything(),
                        "Prescribed rigid rotation of a boundary: 'right: degrees=1 (or angle=rad), "
                        "center=x y z, axis=0 0 1'. In 2D the axis is z. The exact rotation is "
                        "imposed (not its small-angle form). Coordinates may be expressions of geometry "
                        "parameters: center=l/2 0.");
      prm.declare_entry("Rigid", "", Patterns::Anything(),
                        "Boundaries that move as rigid bodies loaded by a force and a moment, "
                        "their translation and rotation unknowns (a torque drive, a pure end "
                        "moment): 'right: moment=M (2D, about z) or moment=Mx My Mz (3D), "
                        "force=Fx Fy [Fz], center=x y [z]'. The moment acts about the center "
                        "(default: the centroid of the boundary's nodes), which moves with the "
                        "boundary; force and moment keep their direction (dead loads), are totals "
                        "over the thickness in 2D and scale with the load factor; numbers or expressions of "
                        "geometry parameters. Exact rigid "
                        "motion at finite strain (any rotation). Gives rigid_rotation_<name>_<z|x y "
                        "z> (radians) and rigid_displacement_<name>_<x|y|z> (of the center). "
                        "Linear and nonlinear static analyses; a rigid boundary shares no node "
                        "with a supported boundary.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Loads");
    {
      prm.declare_entry("Traction", "", Patterns::Anything(),
                        "Traction vector (force per area) on boundaries: 'top: 0 -1 0'.");
      prm.declare_entry("Total force", "", Patterns::Anything(),
                        "Total force spread uniformly over a boundary: 'right: 0 -1'.");
      prm.declare_entry("Pressure", "", Patterns::Anything(),
                        "Pressure (force per area) normal to boundaries, positive pushing on the "
                        "body (against the outward normal): 'inner: 2; outer: 0.5*(1+y/10)', a "
                        "number or an expression of x, y, z and geometry parameters. On the "
                        "undeformed boundary: linear analyses; at finite strain use Finite "
                        "strain/Follower pressure.");
      prm.declare_entry("Body force", "", Patterns::Anything(),
                        "Force per volume on every body: '0 -9.81 0'.");
      prm.declare_entry("Gravity", "", Patterns::Anything(),
                        "Acceleration of gravity: body force = density * gravity.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry("Method", "auto", Patterns::Selection("auto|matrix-free|cg-amg|direct"),
                        "auto: matrix-free for degree >= 2 on quadrilaterals/hexahedra in linear "
                        "static analyses, else MUMPS below 30000 DoFs, else cg-amg; an iterative "
                        "solve that fails to converge in 300 iterations is redone with MUMPS (the "
                        "log says so). matrix-free: CG on the operator without a stored matrix, "
                        "preconditioned by a p-multigrid (degree p..1, Chebyshev smoothing) with "
                        "PETSc GAMG on degree 1 (linear static, quadrilaterals/hexahedra; "
                        "otherwise cg-amg is used and the log says so). cg-amg: conjugate gradients "
                        "with PETSc GAMG on the assembled matrix, given its block size and the "
                        "rigid-body modes. direct: MUMPS LU.");
      prm.declare_entry("Relative tolerance", "1e-10", Patterns::Double(0, 1),
                        "Residual reduction of the iterative solver.");
      prm.declare_entry("Maximum iterations", "2000", Patterns::Integer(1),
                        "Iterations before the iterative solver gives up.");
      prm.declare_entry("PETSc options", "", Patterns::Anything(),
                        "Extra PETSc options, e.g. '-pc_gamg_threshold 0.02'.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Quantities");
    {
      prm.declare_entry("Points", "", Patterns::Anything(),
                        "Named points for displacement output: 'tip: 48 60; mid: 24 52'. "
                        "Gives displacement_<name>_<x|y|z>. Coordinates may be expressions of geometry "
                        "parameters: 'p1: 0.4*L H/4 0'.");
      prm.declare_entry("Reactions", "", Patterns::Anything(),
                        "Boundaries whose reaction force and moment are reported, with the moment "
                        "point (default: origin; rotation-driven boundaries: the rotation "
                        "center): 'left; right: 100 5 0'.");
      prm.declare_entry("Mean displacements", "", Patterns::Anything(),
                        "Boundaries whose average displacement is reported: 'right, top'.");
      prm.declare_entry("Rotations", "", Patterns::Anything(),
                        "Boundaries whose best-fit rigid rotation is reported: 'right'.");
      prm.declare_entry("Stress points", "", Patterns::Anything(),
                        "Named points for stress output: 'hole: 10 0; root: L/2 H/2'. Gives "
                        "stress_<name>_<xx|yy|zz|xy[|xz|yz]> (Cauchy, from the stress field "
                        "recovered by L2 projection onto continuous elements of the displacement's "
                        "degree), von_mises_<name>, principal_stress_<name>_<1|2|3> (largest "
                        "first), and the components and von Mises with the suffix _raw (from the "
                        "displacement gradient in the cell holding the point: discontinuous "
                        "between cells).");
      prm.declare_entry("Region maxima", "", Patterns::Anything(),
                        "Bodies (physical groups of full dimension) whose peak strain and stress "
                        "are reported with where they occur: 'flexure_A, flexure_B' ('*': every "
                        "body). Gives max_principal_strain_in_<body> (largest principal strain: "
                        "small strain in linear analyses, engineering lambda_1 - 1 at finite "
                        "strain; in-plane in 2D), max_von_mises_in_<body> and the reference "
                        "coordinates of each (_x, _y, _z), sampled at quadrature points and "
                        "element nodes; per step in a nonlinear curve.csv. Linear static, "
                        "linkage and nonlinear static analyses.");
      prm.declare_entry("Derived", "", Patterns::Anything(),
                        "Quantities computed from others with muparser: "
                        "'J = reaction_moment_right_x / (G * twist)'. Names of quantities, "
                        "geometry parameters, E, nu, G and thickness may be used.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Comparison");
    {
      prm.declare_entry("Checks", "", Patterns::Anything(),
                        "Quantities compared with closed forms: "
                        "'displacement_tip_y ~ timoshenko_cantilever_deflection(P=1, L=L, ...); ...'. "
                        "Arguments are muparser expressions of geometry parameters, E, nu, G, "
                        "thickness and quantities. See the closed-form list in --help.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Output");
    {
      prm.declare_entry("Directory", "", Patterns::Anything(),
                        "Where results go; empty: results/<case file name>.");
      prm.declare_entry("Fields", "true", Patterns::Bool(),
                        "Write HDF5 + XDMF fields (displacement, strain, stress, von Mises, "
                        "material and partition id) for ParaView.");
    }
    prm.leave_subsection();
  }

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
        first_pass.leave_subsection();
        refuse_unreadable_mesh_name(mesh_name, file);
        parsed.mesh_file = resolve_mesh_file(mesh_name, file);
        if (parsed.mesh_file.empty())
          throw InputError("case file '" + file +
                           "': Geometry/Mesh file is empty; expected a .geo or .msh file");
        try
          {
            geometry_parameters = read_geometry_parameters(parsed.mesh_file);
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
    p.mesh_partition     = prm.get("Mesh partition");
    p.curved_boundaries  = prm.get_bool("Curved boundaries");
    p.formulation        = prm.get("Formulation") == "mixed" ? Formulation::mixed : Formulation::displacement;
    prm.leave_subsection();

    prm.enter_subsection("Material");
    p.thickness   = prm.get_double("Thickness");
    if (!(p.thickness > 0) || !std::isfinite(p.thickness))
      throw InputError("case file '" + p.case_file + "', Material/Thickness: expected a positive "
                       "number (the out-of-plane thickness of a 2D model), got " +
                       prm.get("Thickness"));
    p.unit_system = prm.get("Unit system");
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
    p.solver_method         = prm.get("Method");
    p.solver_tolerance      = prm.get_double("Relative tolerance");
    p.solver_max_iterations = prm.get_integer("Maximum iterations");
    p.petsc_options         = prm.get("PETSc options");
    prm.leave_subsection();

    prm.enter_subsection("Quantities");
    p.points             = prm.get("Points");
    p.reactions          = prm.get("Reactions");
    p.mean_displacements = prm.get("Mean displacements");
    p.rotations          = prm.get("Rotations");
    p.derived            = prm.get("Derived");
    p.region_maxima      = prm.get("Region maxima");
    p.stress_points      = prm.get("Stress points");
    prm.leave_subsection();

    prm.enter_subsection("Comparison");
    p.checks = prm.get("Checks");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    p.output_directory = prm.get("Directory");
    p.write_fields     = prm.get_bool("Fields");
    prm.leave_subsection();
    if (p.output_directory.empty())
      p.output_directory = default_output_directory(p.case_file);
    return p;
  }
} // namespace compliant
