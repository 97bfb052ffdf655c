// Quarter of a bar with two opposite smooth notches (a spline-profiled notch flexure), 2D,
// structured quadrilaterals (or triangles with quads = 0): the bar is 2 L long and 2 H high, the
// notches d deep and 2 c long, centred on x = 0; the quarter x in [0, L], y in [0, H]. Each notch
// is a gmsh Bezier curve of degree 6 from its root (0, H - d) to (c, H) whose control points are
// spaced evenly in x, so that it is the graph y = H - d (1 - (x/c)^2)^3: even in x (smooth across
// the symmetry plane x = 0) and meeting the flat edge with its slope and curvature (both 0); its
// radius at the root is c^2 / (6 d) (1 at c = 3, d = 1.5). Two blocks split by the line x = c:
// nn cells along the notch, nf along the flat part, ny through the height.
// Boundaries: notch (the Bezier curve), top (the flat edge y = H), x_axis (y = 0: symmetry, hold y),
// y_axis (x = 0: symmetry, hold x), right (x = L: the load). Body: bar.
DefineConstant[ L = {10, Name "Parameters/L", Help "half length of the bar"} ];
DefineConstant[ H = {2.5, Name "Parameters/H", Help "half height of the bar"} ];
DefineConstant[ d = {1.5, Name "Parameters/d", Help "depth of each notch"} ];
DefineConstant[ c = {3, Name "Parameters/c", Help "half length of each notch"} ];
DefineConstant[ nn = {4, Name "Parameters/nn", Help "cells along the notch"} ];
DefineConstant[ nf = {4, Name "Parameters/nf", Help "cells along the flat part"} ];
DefineConstant[ ny = {2, Name "Parameters/ny", Help "cells through the half height"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (L <= 0 || H <= 0 || d <= 0 || d >= H || c <= 0 || c >= L || nn < 1 || nf < 1 || ny < 1)
  Error("spline_notch_2d.geo: need L, H > 0, 0 < d < H, 0 < c < L and nn, nf, ny >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0}; Point(2) = {c, 0, 0}; Point(3) = {L, 0, 0}; Point(4) = {L, H, 0};
Point(5) = {c, H, 0}; Point(6) = {0, H - d, 0};
// Bernstein coefficients of 1 - (1 - t^2)^3 = 3 t^2 - 3 t^4 + t^6: 0, 0, 0.2, 0.6, 1, 1, 1.
Point(7) = {c / 6, H - d, 0}; Point(8) = {c / 3, H - 0.8 * d, 0}; Point(9) = {c / 2, H - 0.4 * d, 0};
Point(10) = {2 * c / 3, H, 0}; Point(11) = {5 * c / 6, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {2, 5};
Bezier(6) = {6, 7, 8, 9, 10, 11, 5}; Line(7) = {6, 1};
Curve Loop(1) = {1, 5, -6, 7}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -5}; Plane Surface(2) = {2};
Transfinite Curve{1, 6} = nn + 1; Transfinite Curve{2, 4} = nf + 1; Transfinite Curve{3, 5, 7} = ny + 1;
Transfinite Surface{1} = {1, 2, 5, 6}; Transfinite Surface{2} = {2, 3, 4, 5};
If (quads) Recombine Surface{1, 2}; EndIf
Physical Curve("x_axis") = {1, 2}; Physical Curve("right") = {3}; Physical Curve("top") = {4};
Physical Curve("notch") = {6}; Physical Curve("y_axis") = {7};
Physical Surface("bar") = {1, 2};
