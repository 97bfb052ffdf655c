// A shift of the perfect geometry (Geometry/Imperfection), given per cell as the values of a
// continuous FE_Q vector field at the cell's DoFs, so that any problem built on the same mesh takes
// it as its mapping (the perfect, possibly curved, geometry plus the shift) without sharing DoFs.
#pragma once

#include <deal.II/grid/cell_id.h>

#include <map>
#include <string>
#include <vector>

namespace compliant
{
  struct GeometryImperfection
  {
    unsigned int degree = 0; // of the FE_Q components
    // Every locally owned cell: the shift at its DoFs, in the order of FESystem(FE_Q(degree), dim).
    std::map<dealii::CellId, std::vector<double>> cell_shift;
  };
} // namespace compliant
