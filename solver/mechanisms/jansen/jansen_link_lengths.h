// Dimensions of the eight-link Jansen (Strandbeest) leg.
//
// Joints (seed paper, Kartal & Kavlak, Fig. 5-6): E and A are the fixed pivots
// (A is the crank axle), B the crank pin, CDE and FGH rigid ternary links, H the
// foot. Link vectors and the paper's symbols (the pdf text lost the primes):
//   r1   = E->A  (ground)          r2   = A->B (crank)
//   r3   = B->C                    r4   = B->G
//   r5   = C->E                    r5'  = E->D      r5'' = |CD|  (ternary CDE)
//   r6   = G->E                    r7   = D->F
//   r8   = F->G                    r8'  = G->H      r8'' = |FH|  (ternary FGH)
#pragma once

#include <string>

namespace compliant
{
  namespace jansen
  {
    struct JansenLinkLengths
    {
      double ea = 0.; // r1, ground link between the fixed pivots
      double ab = 0.; // r2, crank
      double bc = 0.; // r3
      double bg = 0.; // r4
      double ce = 0.; // r5
      double de = 0.; // r5'
      double cd = 0.; // r5''
      double eg = 0.; // r6
      double df = 0.; // r7
      double fg = 0.; // r8
      double gh = 0.; // r8'
      double fh = 0.; // r8''
      // theta1: direction of E->A, counter-clockwise from the horizontal (the
      // ground line of the walking leg), in radians.
      double ground_angle = 0.;
    };

    // The leg of the seed paper (mm), theta1 = 11.6 deg. These are Jansen's
    // "holy numbers" scaled by 5, except FG = 183 (Jansen 5 x 36.7 = 183.5) and
    // FH = 328 (5 x 65.7 = 328.5), which the authors re-tuned in Cinderella.
    JansenLinkLengths paper_link_lengths();

    // Theo Jansen's published "holy numbers" a..m (as listed e.g. at
    // strand-beest.blogspot.com/2014/11 and unseel.com/engineering/jansen-linkage)
    // scaled by 5 to mm:
    // the crank axle A lies a = 38 to the side of and l = 7.8 above the pivot E,
    // so |EA| = 5 sqrt(38^2 + 7.8^2) = 193.96 and theta1 = atan(7.8/38) = 11.60 deg.
    JansenLinkLengths jansen_original_link_lengths();

    // Throws std::invalid_argument naming the first length that is not a
    // positive finite number, a ternary link that violates the triangle
    // inequality, or a non-finite ground angle.
    void validate(const JansenLinkLengths &lengths);
  } // namespace jansen
} // namespace compliant
