// Linearized buckling about the linear static state: (K + lambda K_sigma) phi = 0, K_sigma the
// geometric stiffness of the stress under the case's loads and prescribed displacements (lambda
// scales both). SLEPc Krylov-Schur with shift-and-invert about zero (MUMPS), so the factors nearest
// zero come first, either sign: a negative factor buckles the part under the reversed loads.
// Reports buckling_factor_<n> (ordered by magnitude), the reference state's quantities, and the
// mode shapes (largest displacement 1) as fields.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis buckling_analysis();
} // namespace compliant
