// Quarter of a rectangular plate with a central circular hole (Kirsch), 2D, structured
// quadrilaterals (or triangles with quads = 0): hole radius a, plate half-width W (along x) and
// half-height H (along y), the quarter x >= 0, y >= 0. Two transfinite blocks split by the line
// from the hole at 45 degrees to the corner (W, H); nr cells from the hole outward, graded so that
// the outermost is g times as long as the one at the hole (g = 1: uniform; the same g at any nr,
// so doubling nr and nc halves every cell), nc cells around each 45-degree arc.
// Boundaries: hole (r = a), x_sym (y = 0: symmetry, hold y), y_sym (x = 0: symmetry, hold x),
// right (x = W), top (y = H). Body: plate.
DefineConstant[ a = {1, Name "Parameters/a", Help "hole radius"} ];
DefineConstant[ W = {5, Name "Parameters/W", Help "half-width along x (the load direction)"} ];
DefineConstant[ H = {5, Name "Parameters/H", Help "half-height along y"} ];
DefineConstant[ nr = {4, Name "Parameters/nr", Help "cells from the hole outward"} ];
DefineConstant[ nc = {4, Name "Parameters/nc", Help "cells around each 45-degree arc of the hole"} ];
DefineConstant[ g = {1, Name "Parameters/g", Help "outermost / innermost radial cell length (1: uniform)"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (a <= 0 || W <= a || H <= a || nr < 1 || nc < 1 || g <= 0)
  Error("plate_circular_hole_2d.geo: need 0 < a < W, a < H, nr >= 1, nc >= 1 and g > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
c = a * Sqrt(0.5);
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {W, 0, 0}; Point(4) = {W, H, 0}; Point(5) = {0, H, 0};
Point(6) = {0, a, 0}; Point(7) = {c, c, 0};
Line(1) = {2, 3};     // x_sym, outward from the hole
Line(2) = {3, 4};     // right
Line(3) = {4, 5};     // top
Line(4) = {6, 5};     // y_sym, outward from the hole
Line(5) = {7, 4};     // block divider, outward from the hole
Circle(6) = {2, 1, 7}; Circle(7) = {7, 1, 6};
Curve Loop(1) = {1, 2, -5, -6}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 3, -4, -7}; Plane Surface(2) = {2};
r = (nr > 1) ? g^(1 / (nr - 1)) : 1; // growth from one cell to the next
Transfinite Curve{1, 4, 5} = nr + 1 Using Progression r;
Transfinite Curve{2, 3, 6, 7} = nc + 1;
Transfinite Surface{1}; Transfinite Surface{2};
If (quads) Recombine Surface{1, 2}; EndIf
Physical Curve("x_sym") = {1}; Physical Curve("right") = {2}; Physical Curve("top") = {3};
Physical Curve("y_sym") = {4}; Physical Curve("hole") = {6, 7};
Physical Surface("plate") = {1, 2};
