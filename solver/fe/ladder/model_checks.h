// Two of the ladder's decisions as plain functions of what a linear rung measured:
// (c) linear or finite strain, from the largest material rotation theta (a linear answer is off by
// its geometric error, of order theta^2, whatever the mesh); (b) whether a plane-stress model may
// stand for the 3D solid it models, from the out-of-plane energy bound
// (quantities/out_of_plane_bound.h) relative to the strain energy.
#pragma once

#include <string>

namespace compliant
{
  struct GeometricVerdict
  {
    bool        finite_strain = false; // climb in finite strain instead
    std::string reason;
  };

  GeometricVerdict geometric_verdict(double largest_rotation, double target, bool allow_finite_strain);

  struct OutOfPlaneVerdict
  {
    std::string reason;   // the bound and what it means, printed and written to the summary
    std::string needs_3d; // non-empty: a plane-stress model standing in cannot stand for the 3D part
    bool        bound_shares_target = false; // estimate + bound must meet the target
  };

  // bound: |U_3D - U| / U; k: the rung (counted from 0); stand_in: the plane-stress model answers
  // for a 3D part (Target/Paired model). The bound tightens as the mesh resolves the out-of-plane
  // field: a coarse rung gives way only when the bound is twice the target (cantilever W = 1:
  // 0.24 % on the first rung, 0.13 % converged), from the third rung on at the target.
  OutOfPlaneVerdict out_of_plane_verdict(double bound, double thickness, double target, bool stand_in,
                                         unsigned int k);
} // namespace compliant
