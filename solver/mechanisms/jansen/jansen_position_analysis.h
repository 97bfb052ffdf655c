// Position analysis of the Jansen leg from the link lengths alone.
//
// Frame: origin at the fixed pivot E, x horizontal (along the ground the foot
// walks on), y up; all angles counter-clockwise from +x. theta1 is the
// direction of E->A (11.6 deg in the seed paper: Jansen's crank axle sits 38
// units to the side of and 7.8 above the pivot). The crank angle theta2 is the
// direction of A->B in the same frame, exactly the paper's theta2.
//
// Assembly: the crank fixes B; then four dyads are closed by circle
// intersections in the order C (BC, CE), G (BG, EG), D (DE, CD of the rigid
// CDE), F (DF, FG), H (GH, FH of the rigid FGH). This is the closed-form
// solution of the paper's loop equations (1)-(3) and (7).
#pragma once

#include <mechanisms/jansen/circle_intersection.h>
#include <mechanisms/jansen/jansen_joints.h>
#include <mechanisms/jansen/jansen_link_lengths.h>

#include <array>

namespace compliant
{
  namespace jansen
  {
    // Side of each dyad's free joint, seen from the first centre towards the
    // second (see intersect_circles). The defaults are Jansen's working
    // assembly, the one drawn in the paper's Fig. 5 and reproducing its printed
    // angles: C above line B->E, G below it, D outboard (left) of E->C, F below
    // line D->G, H below line G->F (the foot points down). Kept fixed over the
    // whole turn: the leg never passes a dead point, so no branch switch occurs.
    struct AssemblyBranches
    {
      Side c = Side::right; // centres B, E
      Side g = Side::left;  // centres B, E
      Side d = Side::left;  // centres E, C
      Side f = Side::right; // centres D, G
      Side h = Side::left;  // centres G, F
    };

    // Directions of the paper's link vectors (radians, in [0, 2 pi)); see
    // jansen_link_lengths.h for which joints each one joins.
    struct LinkAngles
    {
      double theta1  = 0.; // E->A
      double theta2  = 0.; // A->B, crank
      double theta3  = 0.; // B->C
      double theta4  = 0.; // B->G
      double theta5  = 0.; // C->E
      double theta5p = 0.; // E->D, rigid with theta5
      double theta6  = 0.; // G->E
      double theta7  = 0.; // D->F
      double theta8  = 0.; // F->G
      double theta8p = 0.; // G->H, rigid with theta8
    };

    struct JansenPose
    {
      JointVectors positions; // mm (units of the link lengths), E at the origin
      LinkAngles   angles;
    };

    // Assembles the leg at crank angle theta2 (radians). Throws
    // std::invalid_argument if the lengths are invalid or a dyad cannot close
    // at this crank angle (naming the joint and the crank angle).
    JansenPose solve_position(const JansenLinkLengths &lengths,
                              const double             theta2,
                              const AssemblyBranches  &branches = AssemblyBranches());

    // All joint coordinates A..H at crank angle theta2: what a structural model
    // of the leg needs.
    JointVectors joint_positions(const JansenLinkLengths &lengths,
                                 const double             theta2,
                                 const AssemblyBranches  &branches = AssemblyBranches());

    // Residuals (length units) of the paper's loop equations, from the angles alone:
    //   [0,1] (1) r1 mu1 + r2 mu2 + r3 mu3 + r5 mu5 = 0          loop E-A-B-C-E
    //   [2,3] (2) r1 mu1 + r2 mu2 + r4 mu4 + r6 mu6 = 0          loop E-A-B-G-E
    //   [4,5] (3) r6 mu6 + r5' mu5' + r7 mu7 + r8 mu8 = 0        loop G-E-D-F-G
    //   [6]   |r5 mu5 + r5' mu5'| - |CD|                           CDE stays rigid
    //   [7]   |r8 mu8 + r8' mu8'| - |FH|                           FGH stays rigid
    // and [8,9] the foot equation (7), r_H - (-r6 mu6 + r8' mu8') = 0, which
    // ties the angles to the joint positions. Zero to round-off for a
    // consistent pose.
    std::array<double, 10> loop_closure_residuals(const JansenLinkLengths &lengths,
                                                  const JansenPose        &pose);
  } // namespace jansen
} // namespace compliant
