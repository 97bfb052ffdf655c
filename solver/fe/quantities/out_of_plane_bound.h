// How far a plane-stress answer can be from the 3D solid it stands for: a computable bound on the
// energy difference between the 2D solution and the 3D solution of the same prismatic part
// (thickness b, loads and supports uniform through it, the z faces free).
//
// Two energy principles bracket the 3D strain energy U_3D. The plane-stress stresses are
// statically admissible in 3D (equilibrium, free z faces), so by the complementary-energy principle
// the 3D part is at least as stiff. A kinematically admissible 3D field built from the 2D one,
// v = (u_x, u_y, z psi(x, y)) with psi = 0 on the supported edges, bounds it from the other side
// by the potential-energy principle. The difference between the two is
//   dU = b * min_psi integral [ (lambda + 2 mu)/2 (psi - eps_zz)^2 + G b^2/24 |grad psi|^2 ] dA,
// with eps_zz = -lambda/(lambda + 2 mu) (eps_xx + eps_yy) the plane-stress out-of-plane strain:
// |U_3D - U_ps| <= dU, whether the part is loaded by forces or driven by displacements. psi is
// found by one scalar solve (a screened Poisson problem of length b sqrt(G / (12 (lambda + 2 mu))))
// on the 2D mesh; any psi of the finite element space gives a valid bound. dU / U_ps is then the
// relative bound for the strain energy and for the stiffness or compliance of a single load or
// drive (2 U / theta^2, 2 U / F^2). It scales as (b / l)^2 for an in-plane length l of the strain
// field, and as b / l near supported edges (the anticlastic restraint of a clamp).
#pragma once

namespace compliant
{
  template <int dim>
  class LinearElasticProblem;

  struct OutOfPlaneBound
  {
    double energy_difference = 0; // dU (same units as the strain energy)
    unsigned int n_dofs      = 0; // of the scalar psi problem
  };

  // For a solved plane-stress problem (displacement formulation). Collective.
  OutOfPlaneBound plane_stress_out_of_plane_bound(const LinearElasticProblem<2> &problem);
} // namespace compliant
