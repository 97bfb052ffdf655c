// The case file of section_torsion: deal.II ParameterHandler text in the style of the main
// solver's case files (input/case_file.h), with the .geo file's ONELAB constants as
// Geometry/Parameters.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include "input/case_file.h"
#include "mesh/gmsh_geometry.h"

#include <map>
#include <string>
#include <vector>

namespace compliant::section
{
  struct SectionCase
  {
    std::string                   case_file;
    std::string                   mesh_file; // resolved path
    std::map<std::string, double> geometry_parameters;

    unsigned int element_degree     = 2;
    unsigned int global_refinements = 0;

    double shear_modulus   = 0; // given, or E / (2 (1 + nu))
    double youngs_modulus  = 0;
    double poissons_ratio  = 0;
    double torque          = 1;

    std::string derived, checks;

    std::string output_directory;
    bool        write_fields = true;
  };

  void declare_section_parameters(dealii::ParameterHandler             &prm,
                                  const std::vector<GeometryParameter> &geometry_parameters);

  // Two passes like the main solver: the mesh file named in the case (after --set overrides)
  // decides which Geometry/Parameters exist. Throws InputError naming the file and the entry.
  SectionCase read_section_case(const CommandLine &command_line, dealii::ParameterHandler &prm);
} // namespace compliant::section
