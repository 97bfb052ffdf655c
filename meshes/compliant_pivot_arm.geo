// One-piece compliant pivot carrying an arm (issue 13, item 5: the morphing-wing spar, seed 001), 2D,
// in its printed pose = precision position 1. The synthesis over the paper's Table 3 finds the four
// spar positions to be a near-pure rotation about one pole (burmester_synthesis: single_pivot.csv),
// so the mechanism is one revolute joint, made here as a flexure: a straight strip of length lk and
// in-plane thickness t centred on the pole P and lying along the arm, root fillets of radius rf*t.
// Behind it a ground pad (clamped), ahead of it the arm, W wide, reaching past the spar point S1.
// Coordinates in chords (as the synthesis), scaled by the chord c in mm.
// Boundaries: ground (the pad's edges except the flexure root: clamp it), arm_root (the arm's face
//   beside the flexure root, where a servo would grip it: a rigid boundary driven by a moment; the
//   rest of the arm carries no load and follows rigidly). A rigid boundary around the whole arm
//   gives the same answer but costs Newton 3x the iterations: each exact rigid projection moves
//   the outline and not the arm's interior nodes.
// Bodies: flexure (fillets included), ground_pad, arm_body.
DefineConstant[ c = {200, Name "Parameters/c", Help "wing chord in mm (the paper's positions are in chords; a small UAV wing)"} ];
DefineConstant[ Px = {1.207022578, Name "Parameters/Px", Help "pole x in chords (single_pivot.csv of the synthesis)"} ];
DefineConstant[ Py = {-0.8296653843, Name "Parameters/Py", Help "pole y in chords"} ];
DefineConstant[ Sx = {0.63747, Name "Parameters/Sx", Help "spar point x at position 1, in chords (Table 3)"} ];
DefineConstant[ Sy = {0.05847, Name "Parameters/Sy", Help "spar point y at position 1, in chords (Table 3)"} ];
DefineConstant[ lk = {10, Name "Parameters/lk", Help "flexure length in mm (straight part, centred on the pole)"} ];
DefineConstant[ t = {2, Name "Parameters/t", Help "flexure in-plane thickness in mm"} ];
DefineConstant[ rf = {0.5, Name "Parameters/rf", Help "root fillet radius as a fraction of t (0: sharp corners, singular strain)"} ];
DefineConstant[ W = {12, Name "Parameters/W", Help "in-plane width of the arm and the ground pad in mm"} ];
DefineConstant[ Lg = {12, Name "Parameters/Lg", Help "length of the ground pad behind the flexure in mm"} ];
DefineConstant[ nt = {4, Name "Parameters/nt", Help "cells through the flexure thickness"} ];
DefineConstant[ hb = {6, Name "Parameters/hb", Help "cell length along the arm and the pad in mm"} ];

r = rf * t;
a = lk / 2 + r;      // pole to body face, along the flexure axis
R = c * Sqrt((Sx - Px) ^ 2 + (Sy - Py) ^ 2);
If (c <= 0 || lk <= 0 || t <= 0 || rf < 0 || W <= t + 2 * r || Lg <= 0 || R <= a + W || nt < 1 || hb <= 0)
  Error("compliant_pivot_arm.geo: need c, lk, t, Lg, hb > 0, rf >= 0, W > t (1 + 2 rf), nt >= 1 and the spar farther from the pole than lk/2 + rf t + W");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
px = c * Px; py = c * Py;
ux = c * (Sx - Px) / R; uy = c * (Sy - Py) / R; nx = uy; ny = -ux;
h0 = t / nt;
nr = Ceil(nt * (Pi * r / 2) / t); If (nr < 1) nr = 1; EndIf
nl = Ceil(nt * lk / t); If (nl < 1) nl = 1; EndIf
// Arm and pad are structured too (an unstructured recombination left odd triangles at some nt):
// ns cells beside the flexure root on each side (half the flexure's cell size), na along the
// arm, ng along the pad (cells of size hb there).
ns = Ceil((W / 2 - t / 2 - r) / (2 * h0)); If (ns < 1) ns = 1; EndIf
na = Ceil((R + W / 2 - a) / hb); If (na < 2) na = 2; EndIf
ng = Ceil(Lg / hb); If (ng < 2) ng = 2; EndIf

// Flexure faces: pf[0], pf[1] at s = -a (q = +, -), pf[2], pf[3] at s = +a.
For k In {0:1}
  sg = (k == 0) ? -1 : 1;
  For j In {0:1}
    sq = (j == 0) ? 1 : -1;
    i = 2 * k + j;
    pf[i] = newp; Point(pf[i]) = {px + sg * a * ux + sq * (t / 2 + r) * nx, py + sg * a * uy + sq * (t / 2 + r) * ny, 0, h0};
    If (r > 0)
      pr[i] = newp; Point(pr[i]) = {px + sg * lk / 2 * ux + sq * t / 2 * nx, py + sg * lk / 2 * uy + sq * t / 2 * ny, 0, h0};
      pc[i] = newp; Point(pc[i]) = {px + sg * lk / 2 * ux + sq * (t / 2 + r) * nx, py + sg * lk / 2 * uy + sq * (t / 2 + r) * ny, 0, h0};
    EndIf
  EndFor
EndFor
fe_line = newl; Line(fe_line) = {pf[0], pf[1]};
fs_line = newl; Line(fs_line) = {pf[2], pf[3]};
If (r > 0)
  arc0 = newl; Circle(arc0) = {pf[0], pc[0], pr[0]};
  side0 = newl; Line(side0) = {pr[0], pr[2]};
  arc1 = newl; Circle(arc1) = {pr[2], pc[2], pf[2]};
  arc2 = newl; Circle(arc2) = {pf[1], pc[1], pr[1]};
  side1 = newl; Line(side1) = {pr[1], pr[3]};
  arc3 = newl; Circle(arc3) = {pr[3], pc[3], pf[3]};
  Transfinite Curve{arc0, arc1, arc2, arc3} = nr + 1;
  cl = newll; Curve Loop(cl) = {fe_line, arc2, side1, arc3, -fs_line, -arc1, -side0, -arc0};
Else
  side0 = newl; Line(side0) = {pf[0], pf[2]};
  side1 = newl; Line(side1) = {pf[1], pf[3]};
  cl = newll; Curve Loop(cl) = {fe_line, side1, -fs_line, -side0};
EndIf
Transfinite Curve{fe_line, fs_line} = nt + 1;
Transfinite Curve{side0, side1} = nl + 1;
flexure = news; Plane Surface(flexure) = {cl};
Transfinite Surface{flexure} = {pf[0], pf[1], pf[3], pf[2]};
Recombine Surface{flexure};

// Corner of a body at s along u and q across from the pole.
Macro BodyPoint
  bp = newp; Point(bp) = {px + s * ux + q * nx, py + s * uy + q * ny, 0, hb};
Return

// Arm: from face +a to R + W/2 (the spar point S1 lies on its axis at s = R).
s = a; q = W / 2; Call BodyPoint;
k1 = bp;  q = -W / 2; Call BodyPoint;
k2 = bp;
s = R + W / 2; Call BodyPoint;
k3 = bp;  q = W / 2; Call BodyPoint;
k4 = bp;
arm_c[] = {};
arm_c[0] = newl; Line(arm_c[0]) = {k1, pf[2]};
arm_c[1] = newl; Line(arm_c[1]) = {pf[3], k2};
arm_c[2] = newl; Line(arm_c[2]) = {k2, k3};
arm_c[3] = newl; Line(arm_c[3]) = {k3, k4};
arm_c[4] = newl; Line(arm_c[4]) = {k4, k1};
cl = newll; Curve Loop(cl) = {arm_c[0], fs_line, arm_c[1], arm_c[2], arm_c[3], arm_c[4]};
arm = news; Plane Surface(arm) = {cl};
// Structured: the root side (pad, flexure face, pad) faces the far end with as many nodes.
Transfinite Curve{arm_c[0], arm_c[1]} = ns + 1;
Transfinite Curve{arm_c[3]} = 2 * ns + nt + 1;
Transfinite Curve{arm_c[2], arm_c[4]} = na + 1;
Transfinite Surface{arm} = {k1, k2, k3, k4};

// Ground pad: from face -a back by Lg.
s = -a; q = W / 2; Call BodyPoint;
g1 = bp;  q = -W / 2; Call BodyPoint;
g2 = bp;
s = -a - Lg; Call BodyPoint;
g3 = bp;  q = W / 2; Call BodyPoint;
g4 = bp;
ground_c[] = {};
ground_c[0] = newl; Line(ground_c[0]) = {g1, pf[0]};
ground_c[1] = newl; Line(ground_c[1]) = {pf[1], g2};
ground_c[2] = newl; Line(ground_c[2]) = {g2, g3};
ground_c[3] = newl; Line(ground_c[3]) = {g3, g4};
ground_c[4] = newl; Line(ground_c[4]) = {g4, g1};
cl = newll; Curve Loop(cl) = {ground_c[0], fe_line, ground_c[1], ground_c[2], ground_c[3], ground_c[4]};
ground = news; Plane Surface(ground) = {cl};
Transfinite Curve{ground_c[0], ground_c[1]} = ns + 1;
Transfinite Curve{ground_c[3]} = 2 * ns + nt + 1;
Transfinite Curve{ground_c[2], ground_c[4]} = ng + 1;
Transfinite Surface{ground} = {g1, g2, g3, g4};

Recombine Surface{arm, ground};

Physical Curve("ground") = {ground_c[]};
Physical Curve("arm_root") = {arm_c[0], arm_c[1]};
Physical Surface("flexure") = {flexure};
Physical Surface("ground_pad") = {ground};
Physical Surface("arm_body") = {arm};
