// Samples of the parametrization of a curve or surface of the model gmsh has open, dense enough
// that Hermite interpolation between them (mesh/sampled_geometry.h) holds the entity to about
// 1e-10 of its size: what the solver keeps of a curved boundary that is no circle, cylinder or
// sphere, since gmsh is gone after meshing and absent on the other ranks.
#pragma once

#include "mesh/sampled_geometry.h"

#include <string>

namespace compliant
{
  // Fills samples for entity (dim 1 or 2, tag); returns "" or why the entity cannot be followed
  // (no finite parametrization, values gmsh cannot give, interpolation that does not converge).
  std::string sample_entity(int dim, int tag, ParametricSamples &samples);
} // namespace compliant
