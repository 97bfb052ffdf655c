// Hertz contact in 3D: a quarter of an elastic block x in [0, L], y in [0, L], z in [-L, 0], its top
// face z = 0 touched at the origin (the corner on both symmetry planes) by a rigid sphere above it.
// Structured hexahedra: a cube [0, c]^2 x [-c, 0] at the origin of m x m x m equal cells, where the
// contact lies (c about 1.5 times the contact radius), and k cells from c to L in each direction
// growing geometrically from the fine cells' size c / m.
// Boundaries: top (z = 0), bottom (z = -L), sym_x (x = 0), sym_y (y = 0), sides (x = L, y = L).
// Body: block.
DefineConstant[ L = {10, Name "Parameters/L", Help "block size (edge of the quarter)"} ];
DefineConstant[ c = {0.75, Name "Parameters/c", Help "edge of the fine cube at the contact"} ];
DefineConstant[ m = {12, Name "Parameters/m", Help "cells across the fine cube"} ];
DefineConstant[ k = {10, Name "Parameters/k", Help "cells from the fine cube to the block's far faces"} ];
If (L <= 0 || c <= 0 || c >= L / 2 || m < 1 || k < 1 || c / m * k > L - c)
  Error("hertz_block_3d.geo: need L > 0, 0 < c < L/2, m >= 1, k >= 1 and k c / m <= L - c (the graded cells must not shrink)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
// The growth ratio g of the k graded cells: h (g^k - 1) / (g - 1) = L - c with h = c / m, by bisection.
h = c / m; lo = 1; hi = 2;
For it In {1 : 200}
  If (h * (hi^k - 1) / (hi - 1) < L - c)
    hi = 2 * hi;
  EndIf
EndFor
For it In {1 : 80}
  g = (lo + hi) / 2;
  If (g > 1 && h * (g^k - 1) / (g - 1) > L - c)
    hi = g;
  Else
    lo = g;
  EndIf
EndFor
g = (lo + hi) / 2;
// Top face: 3 x 3 points, 12 lines, 4 quadrilateral patches.
p = 0;
For j In {0 : 2}
  For i In {0 : 2}
    p += 1; xs[] = {0, c, L}; Point(p) = {xs[i], xs[j], 0};
  EndFor
EndFor
// Lines along x (y = 0, c, L), then along y (x = 0, c, L); all run away from the origin.
l = 0;
For j In {0 : 2}
  l += 1; Line(l) = {3 * j + 1, 3 * j + 2}; Transfinite Curve{l} = m + 1;
  l += 1; Line(l) = {3 * j + 2, 3 * j + 3}; Transfinite Curve{l} = k + 1 Using Progression g;
EndFor
For i In {0 : 2}
  l += 1; Line(l) = {i + 1, i + 4}; Transfinite Curve{l} = m + 1;
  l += 1; Line(l) = {i + 4, i + 7}; Transfinite Curve{l} = k + 1 Using Progression g;
EndFor
// Lines: x-runs 1..6 (y = 0: 1, 2; y = c: 3, 4; y = L: 5, 6), y-runs 7..12 (x = 0: 7, 8; x = c: 9, 10; x = L: 11, 12).
Curve Loop(1) = {1, 9, -3, -7};   Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -4, -9};  Plane Surface(2) = {2};
Curve Loop(3) = {3, 10, -5, -8};  Plane Surface(3) = {3};
Curve Loop(4) = {4, 12, -6, -10}; Plane Surface(4) = {4};
Transfinite Surface{1 : 4}; Recombine Surface{1 : 4};
// Layers down z: m equal ones to depth c, then k growing by g.
counts[] = {}; tops[] = {}; depth = 0;
For i In {1 : m}
  depth += h; counts[] += {1}; tops[] += {depth / L};
EndFor
For i In {1 : k}
  depth += h * g^(i - 1); counts[] += {1}; tops[] += {depth / L};
EndFor
tops[m + k - 1] = 1;
out[] = Extrude {0, 0, -L} { Surface{1 : 4}; Layers{counts[], tops[]}; Recombine; };
e = 1e-6 * L;
Physical Surface("top") = {1 : 4};
Physical Surface("bottom") = Surface In BoundingBox{-e, -e, -L - e, L + e, L + e, -L + e};
Physical Surface("sym_x") = Surface In BoundingBox{-e, -e, -L - e, e, L + e, e};
Physical Surface("sym_y") = Surface In BoundingBox{-e, -e, -L - e, L + e, e, e};
Physical Surface("sides") = {Surface In BoundingBox{L - e, -e, -L - e, L + e, L + e, e},
                              Surface In BoundingBox{-e, L - e, -L - e, L + e, L + e, e}};
Physical Volume("block") = Volume "*";
