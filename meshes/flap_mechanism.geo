// One-piece compliant flap four-bar (seed paper 000, issue 6 item 3), 2D, at its rest pose (the
// printed shape: flap closed, start of the sweep, as flap_prbm's rest_pose = start).
// Pivots: A = (0, 0), D = (L1, 0), B on the crank at angle crank0, C from the loop closure
// (circle-circle intersection, C above AD: flap_prbm's 'minus' branch). At each pivot a straight
// flexure of length lk and in-plane thickness t is centred on the pivot, with root fillets of
// radius rf*t at its four corners: A and B lie along the crank AB, C and D along the rocker DC.
// The link bodies are W wide; the coupler and the ground reach W beyond their flexures (pads) and
// are joined straight between the pads (simple polygons, checked non-degenerate below).
// Boundaries: ground (every edge of the ground body except its flexure roots: clamp it),
//   crank_drive (every edge of the crank body: prescribe its rigid rotation about A).
// Bodies: flexure_A .. flexure_D (fillets included), ground, crank, coupler, rocker.
// Cells: quadrilaterals; flexures structured (nt cells through t), bodies unstructured.
DefineConstant[ L1 = {60, Name "Parameters/L1", Help "ground link AD, pivot to pivot (paper Table 1)"} ];
DefineConstant[ L2 = {10, Name "Parameters/L2", Help "crank AB, pivot to pivot (paper Table 1)"} ];
DefineConstant[ L3 = {65, Name "Parameters/L3", Help "coupler BC, pivot to pivot (paper Table 1)"} ];
DefineConstant[ L4 = {15, Name "Parameters/L4", Help "rocker CD (carries the flap), pivot to pivot (paper Table 1)"} ];
DefineConstant[ crank0 = {105.2122597786562, Name "Parameters/crank0",
  Help "crank angle of the printed (unloaded) pose, degrees from AD: start of the 26 deg flap sweep centred on the 90 deg transmission angle (flap_prbm, rest_pose = start)"} ];
DefineConstant[ lk = {1, Name "Parameters/lk", Help "flexure length l_k (straight part, pivot at its middle); cases/flap/flap_prbm_default.prm"} ];
DefineConstant[ t = {3, Name "Parameters/t", Help "flexure in-plane thickness (the paper's bending thickness h = 3 mm)"} ];
DefineConstant[ rf = {0.25, Name "Parameters/rf", Help "root fillet radius as a fraction of t (0: sharp corners, singular strain)"} ];
DefineConstant[ W = {10, Name "Parameters/W", Help "in-plane width of the link bodies (stiff links: W^3 >> t^3)"} ];
DefineConstant[ nt = {4, Name "Parameters/nt", Help "cells through the flexure thickness"} ];
DefineConstant[ hb = {2, Name "Parameters/hb", Help "cell size in the link bodies (graded to t/nt at the flexures)"} ];

r = rf * t;          // fillet radius
a = lk / 2 + r;      // pivot to body face, along the flexure axis
If (lk <= 0 || t <= 0 || rf < 0 || W <= t + 2 * r || 2 * a >= L2 || 2 * a >= L4 || L1 <= 0 || L3 <= 0 || nt < 1 || hb <= 0)
  Error("flap_mechanism.geo: need lk > 0, t > 0, rf >= 0, W > t (1 + 2 rf), lk + 2 rf t below the crank and rocker lengths L2, L4, L1 > 0, L3 > 0, nt >= 1 and hb > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf

// Pivots and link directions (u along the flexure axis, n = u turned by -90 deg).
th2 = crank0 * Pi / 180;
Bx = L2 * Cos(th2); By = L2 * Sin(th2);
dx = L1 - Bx; dy = -By; d = Sqrt(dx * dx + dy * dy);
aa = (L3 * L3 - L4 * L4 + d * d) / (2 * d);
If (L3 * L3 - aa * aa < 0)
  Error("flap_mechanism.geo: the loop cannot be closed at crank0 = %g deg", crank0);
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
hh = Sqrt(L3 * L3 - aa * aa);
c1x = Bx + aa * dx / d - hh * dy / d; c1y = By + aa * dy / d + hh * dx / d;
c2x = Bx + aa * dx / d + hh * dy / d; c2y = By + aa * dy / d - hh * dx / d;
Cx = (c1y >= c2y) ? c1x : c2x; Cy = (c1y >= c2y) ? c1y : c2y;
u2x = Cos(th2); u2y = Sin(th2); n2x = u2y; n2y = -u2x;
th4 = Atan2(Cy, Cx - L1);
u4x = Cos(th4); u4y = Sin(th4); n4x = u4y; n4y = -u4x;

h0 = t / nt;         // cell size at the flexures
nr = Ceil(nt * (Pi * r / 2) / t); If (nr < 1) nr = 1; EndIf
nl = Ceil(nt * lk / t); If (nl < 1) nl = 1; EndIf

// Flexure at pivot (px, py) along (ux, uy): straight part of length lk and thickness t, fillets
// of radius r into the two body faces at +-a. Face points (s = along, q = across) are stored in
// fe[] (end -a: right, left) and fs[] (end +a: right, left) for the bodies to share.
Macro Flexure
  For k In {0:1}
    sg = (k == 0) ? -1 : 1;
    For j In {0:1}
      sq = (j == 0) ? 1 : -1;
      i = 2 * k + j;
      // face corner (s = +-a, q = +-(t/2 + r)), root (s = +-lk/2, q = +-t/2), arc centre
      pf[i] = newp; Point(pf[i]) = {px + sg * a * ux + sq * (t / 2 + r) * nx, py + sg * a * uy + sq * (t / 2 + r) * ny, 0, h0};
      If (r > 0)
        pr[i] = newp; Point(pr[i]) = {px + sg * lk / 2 * ux + sq * t / 2 * nx, py + sg * lk / 2 * uy + sq * t / 2 * ny, 0, h0};
        pc[i] = newp; Point(pc[i]) = {px + sg * lk / 2 * ux + sq * (t / 2 + r) * nx, py + sg * lk / 2 * uy + sq * (t / 2 + r) * ny, 0, h0};
      EndIf
    EndFor
  EndFor
  fe_line = newl; Line(fe_line) = {pf[0], pf[1]};     // face at s = -a, from +q to -q
  fs_line = newl; Line(fs_line) = {pf[2], pf[3]};     // face at s = +a, from +q to -q
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
  flex = news; Plane Surface(flex) = {cl};
  Transfinite Surface{flex} = {pf[0], pf[1], pf[3], pf[2]};
  Recombine Surface{flex};
Return

// Corner of a body at distance s along (ux, uy) and q across from pivot (px, py): point bp.
Macro BodyPoint
  bp = newp; Point(bp) = {px + s * ux + q * nx, py + s * uy + q * ny, 0, hb};
Return

// (A Call must end its line: gmsh reads the rest of the line before running the macro.)
// The four flexures: A and B along the crank, C and D along the rocker.
ux = u2x; uy = u2y; nx = n2x; ny = n2y;
px = 0; py = 0; Call Flexure;
fA = flex; feA = fe_line; fsA = fs_line; pA[] = pf[];
px = Bx; py = By; Call Flexure;
fB = flex; feB = fe_line; fsB = fs_line; pB[] = pf[];
ux = u4x; uy = u4y; nx = n4x; ny = n4y;
px = Cx; py = Cy; Call Flexure;
fC = flex; feC = fe_line; fsC = fs_line; pC[] = pf[];
px = L1; py = 0; Call Flexure;
fD = flex; feD = fe_line; fsD = fs_line; pD[] = pf[];

// Crank: between face +a of A and face -a of B (along u2).
ux = u2x; uy = u2y; nx = n2x; ny = n2y; px = 0; py = 0;
s = a; q = W / 2; Call BodyPoint;
k1 = bp;  q = -W / 2; Call BodyPoint;
k2 = bp;
s = L2 - a; q = -W / 2; Call BodyPoint;
k3 = bp;  q = W / 2; Call BodyPoint;
k4 = bp;
c[] = {}; c[0] = newl; Line(c[0]) = {k1, pA[2]};
c[1] = newl; Line(c[1]) = {pA[3], k2};
c[2] = newl; Line(c[2]) = {k2, k3};
c[3] = newl; Line(c[3]) = {k3, pB[1]};
c[4] = newl; Line(c[4]) = {pB[0], k4};
c[5] = newl; Line(c[5]) = {k4, k1};
crank_curves[] = c[];
cl = newll; Curve Loop(cl) = {c[0], fsA, c[1], c[2], c[3], -feB, c[4], c[5]};
crank = news; Plane Surface(crank) = {cl};

// Rocker: between face +a of D and face -a of C (along u4, from D).
ux = u4x; uy = u4y; nx = n4x; ny = n4y; px = L1; py = 0;
s = a; q = W / 2; Call BodyPoint;
k1 = bp;  q = -W / 2; Call BodyPoint;
k2 = bp;
s = L4 - a; q = -W / 2; Call BodyPoint;
k3 = bp;  q = W / 2; Call BodyPoint;
k4 = bp;
c[] = {}; c[0] = newl; Line(c[0]) = {k1, pD[2]};
c[1] = newl; Line(c[1]) = {pD[3], k2};
c[2] = newl; Line(c[2]) = {k2, k3};
c[3] = newl; Line(c[3]) = {k3, pC[1]};
c[4] = newl; Line(c[4]) = {pC[0], k4};
c[5] = newl; Line(c[5]) = {k4, k1};
cl = newll; Curve Loop(cl) = {c[0], fsD, c[1], c[2], c[3], -feC, c[4], c[5]};
rocker = news; Plane Surface(rocker) = {cl};

// Coupler: pads beyond face +a of B (along u2) and of C (along u4), joined.
ux = u2x; uy = u2y; nx = n2x; ny = n2y; px = Bx; py = By;
s = a; q = W / 2; Call BodyPoint;
qb1 = bp;  q = -W / 2; Call BodyPoint;
qb2 = bp;
s = a + W; Call BodyPoint;
tb2 = bp;
ux = u4x; uy = u4y; nx = n4x; ny = n4y; px = Cx; py = Cy;
s = a + W; q = W / 2; Call BodyPoint;
tc1 = bp;
s = a; Call BodyPoint;
qc1 = bp;  q = -W / 2; Call BodyPoint;
qc2 = bp;
c[] = {}; c[0] = newl; Line(c[0]) = {qb1, pB[2]};
c[1] = newl; Line(c[1]) = {pB[3], qb2};
c[2] = newl; Line(c[2]) = {qb2, tb2};
c[3] = newl; Line(c[3]) = {tb2, tc1};
c[4] = newl; Line(c[4]) = {tc1, qc1};
c[5] = newl; Line(c[5]) = {qc1, pC[2]};
c[6] = newl; Line(c[6]) = {pC[3], qc2};
c[7] = newl; Line(c[7]) = {qc2, qb1};
cl = newll; Curve Loop(cl) = {c[0], fsB, c[1], c[2], c[3], c[4], c[5], fsC, c[6], c[7]};
coupler = news; Plane Surface(coupler) = {cl};

// Ground: pads beyond face -a of A (along -u2) and of D (along -u4), joined.
ux = u2x; uy = u2y; nx = n2x; ny = n2y; px = 0; py = 0;
s = -a; q = W / 2; Call BodyPoint;
ga1 = bp;  q = -W / 2; Call BodyPoint;
ga2 = bp;
s = -a - W; Call BodyPoint;
ba2 = bp;
ux = u4x; uy = u4y; nx = n4x; ny = n4y; px = L1; py = 0;
s = -a - W; q = W / 2; Call BodyPoint;
bd1 = bp;
s = -a; Call BodyPoint;
gd1 = bp;  q = -W / 2; Call BodyPoint;
gd2 = bp;
c[] = {}; c[0] = newl; Line(c[0]) = {ga1, pA[0]};
c[1] = newl; Line(c[1]) = {pA[1], ga2};
c[2] = newl; Line(c[2]) = {ga2, ba2};
c[3] = newl; Line(c[3]) = {ba2, bd1};
c[4] = newl; Line(c[4]) = {bd1, gd1};
c[5] = newl; Line(c[5]) = {gd1, pD[0]};
c[6] = newl; Line(c[6]) = {pD[1], gd2};
c[7] = newl; Line(c[7]) = {gd2, ga1};
ground_curves[] = c[];
cl = newll; Curve Loop(cl) = {c[0], feA, c[1], c[2], c[3], c[4], c[5], feD, c[6], c[7]};
ground = news; Plane Surface(ground) = {cl};

Recombine Surface{crank, rocker, coupler, ground};
Mesh.Algorithm = 6;               // frontal-Delaunay + blossom recombination (8 crashes gmsh 4.8.4 here)
Mesh.RecombinationAlgorithm = 3;  // blossom full-quad: no triangle left over
Mesh.MeshSizeExtendFromBoundary = 1;

Physical Curve("ground") = {ground_curves[]};
Physical Curve("crank_drive") = {crank_curves[]};
Physical Surface("flexure_A") = {fA};
Physical Surface("flexure_B") = {fB};
Physical Surface("flexure_C") = {fC};
Physical Surface("flexure_D") = {fD};
Physical Surface("ground_body") = {ground};
Physical Surface("crank") = {crank};
Physical Surface("coupler") = {coupler};
Physical Surface("rocker") = {rocker};
