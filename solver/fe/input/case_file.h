// The case file: deal.II ParameterHandler text, declared here once. Everything the user can
// set, with its documentation and default, comes from these declarations (--help prints them).
#pragma once

#include <deal.II/base/parameter_handler.h>

#include "input/imperfection_spec.h"
#include "input/unit_system.h"
#include "linear_algebra/solver_method.h"
#include "mesh/gmsh_geometry.h"
#include "mesh/partition_request.h"

#include <functional>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace compliant
{
  // A user error (bad case file, bad option): reported without a stack trace, exit code 2.
  struct InputError : std::runtime_error
  {
    using std::runtime_error::runtime_error;
  };

  // Model = ...: the case file's words are to_string's.
  enum class Model
  {
    plane_stress,
    plane_strain,
    three_d
  };
  const char *to_string(Model model);

  // Discretization/Formulation = ... (linear analyses).
  enum class Formulation
  {
    displacement,
    mixed // Q_p displacement with a discontinuous P_(p-1) pressure
  };
  const char *to_string(Formulation formulation);

  struct CaseParameters
  {
    std::string              case_file;
    std::vector<std::string> overrides; // the --set entries it was read with, "Section/Name=value"
    Model       model = Model::plane_stress;
    int         dimension = 2;
    std::string analysis;

    std::string                   mesh_file; // resolved path
    std::map<std::string, double> geometry_parameters;
    std::vector<ImperfectionMode> imperfection; // Geometry/Imperfection (nonlinear static)
    std::uint64_t maximum_cells      = 0; // Geometry/Maximum cells; 0: automatic
    double        meshing_time_limit = 0; // Geometry/Meshing time limit in s; 0: automatic

    unsigned int element_degree     = 2;
    unsigned int global_refinements = 0;
    PartitionRequest mesh_partition = PartitionRequest::automatic;
    bool         curved_boundaries  = true;   // circles, cylinders, spheres follow the geometry
    // Degree of the mapping of quadrilaterals/hexahedra where a boundary is curved; 0: the
    // element's (isoparametric).
    unsigned int curved_mapping_degree = 0;
    Formulation  formulation        = Formulation::displacement; // linear analyses
    // Discretization/Integration = reduced: p Gauss points per direction for the stiffness, plus
    // hourglass_stiffness times the fully integrated one (discretization/reduced_integration.h).
    bool         reduced_integration = false;
    double       hourglass_stiffness = 0.03;
    // Local refinements after the global ones, one set of refine flags (per active cell) per
    // cycle: set by the model ladder's adaptive rungs, never read from the case file.
    std::vector<std::vector<bool>> adaptive_refinements;

    double      thickness = 1.0;
    UnitSystem  unit_system = UnitSystem::si;
    std::string materials;

    std::string clamped, displacement, rotation, rigid;
    std::string traction, total_force, body_force, gravity;
    std::string pressure; // 'boundary: p' on the undeformed normal (linear analyses)

    SolverMethod solver_method = SolverMethod::automatic;
    double      solver_tolerance = 1e-10;
    unsigned    solver_max_iterations = 1000;
    std::string petsc_options;
    bool        long_edge_coarse_space = true; // Linear solver/Coarse space = auto

    std::string points, reactions, mean_displacements, rotations, derived;
    std::string region_maxima; // bodies whose peak strain and stress are reported
    bool        error_estimates = false; // Quantities/Error estimates: each quantity's estimate (linear static)
    std::string stress_points; // 'name: x y [z]': stress components, von Mises, principal
    std::string checks;

    std::string output_directory;
    bool        write_fields = true;
    bool        write_pictures = true; // picture(s) and report.html beside the summary
  };

  // Declares every entry (input/case_declarations.cc). Geometry parameters of the given .geo file
  // become entries of "Geometry/Parameters" with the file's defaults and help strings.
  void declare_case_parameters(dealii::ParameterHandler             &prm,
                               const std::vector<GeometryParameter> &geometry_parameters);

  // Declares the subsection "Parameters" of the current subsection (Geometry): one number entry
  // per parameter of the .geo file, with its default and help string. Shared by every parameter
  // file read with read_parameter_file (the case file, section_torsion's case file).
  void declare_geometry_parameters(dealii::ParameterHandler             &prm,
                                   const std::vector<GeometryParameter> &geometry_parameters);

  struct CommandLine
  {
    std::string              case_file;
    std::vector<std::string> overrides; // "Section/Name=value"
    bool                     help  = false;
    bool                     check = false;
  };

  CommandLine parse_command_line(int argc, char **argv);

  // Two-pass reading of any parameter file whose geometry parameters come from its .geo file:
  // pass 1 finds Geometry/Mesh file, its ONELAB parameters are declared (by `declare`), pass 2
  // parses the file and applies the --set overrides. Throws InputError naming file and entry.
  struct ParsedParameterFile
  {
    std::string                   mesh_file; // resolved
    std::map<std::string, double> geometry_parameters;
  };
  using ParameterDeclarer =
    std::function<void(dealii::ParameterHandler &, const std::vector<GeometryParameter> &)>;
  ParsedParameterFile read_parameter_file(const CommandLine &command_line,
                                          dealii::ParameterHandler &prm,
                                          const ParameterDeclarer &declare);

  // Reads the case file in two passes (the .geo file decides which geometry parameters exist),
  // applies --set overrides and validates values. Throws InputError naming file and entry.
  CaseParameters read_case(const CommandLine &command_line, dealii::ParameterHandler &prm);

  // results/<prefix><case file name without extension>: where a case writes when Output/Directory
  // is empty.
  std::string default_output_directory(const std::string &case_file, const std::string &prefix = "");

  // Where a mesh file named in a case is looked for: next to the case, then meshes/.
  std::string resolve_mesh_file(const std::string &name, const std::string &case_file);
} // namespace compliant
