// Modal analysis: the lowest natural frequencies and mode shapes of K x = omega^2 M x with the
// consistent mass matrix, by SLEPc Krylov-Schur with shift-and-invert (MUMPS), so that free and
// partly supported structures work. Dirichlet boundaries are held fixed (prescribed values are
// ignored), loads are ignored. Reports frequency_<n> in Hz (cycles per time unit of the unit
// system: SI and mm-N-MPa-t both give Hz), effective modal masses per direction and their
// fractions of the total mass; writes the mode shapes as fields.
#pragma once

#include "analyses/analysis.h"

namespace compliant
{
  Analysis modal_analysis();
} // namespace compliant
