// Rung (b) across dimensions: a case names the model of the other dimension that stands for the
// same part (Target/Paired model). A 3D part names its plane-stress model, which the ladder tries
// first; a plane-stress model names its 3D part, which the ladder climbs when the out-of-plane
// bound shows that 2D is not enough. Same-named geometry parameters carry over from the case on
// the command line (after its --set overrides), and the spec may set more entries from them.
#pragma once

#include <deal.II/base/parameter_handler.h>

#include <mpi.h>

#include "input/case_file.h"
#include "mesh/gmsh_geometry.h"

#include <memory>
#include <string>

namespace compliant
{
  struct PairedModel
  {
    std::unique_ptr<dealii::ParameterHandler> prm;
    CaseParameters                            parameters;
    MeshedGeometry                            geometry;
  };

  // spec: 'file[: Section/Entry=expression, ...]', the file next to the primary case (else as
  // given, from the working directory), the expressions over the primary's geometry parameters
  // (and `thickness` when the primary is 2D). The primary's --set Material/Materials and
  // Material/Unit system carry over. The paired model writes to the primary's output directory.
  // Throws InputError naming the case file, Target/Paired model and what was expected: a linear
  // static case of the other dimension (its 2D side plane stress), with the same materials (E, nu)
  // and the same volume (within 2 %, on the unrefined meshes). Loads and supports are not compared.
  PairedModel read_paired_model(const CaseParameters &primary, const MeshedGeometry &primary_geometry,
                                const std::string &spec, MPI_Comm communicator);
} // namespace compliant
