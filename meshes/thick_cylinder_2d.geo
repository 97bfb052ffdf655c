// Quarter of a thick-walled cylinder (Lame), 2D, structured quadrilaterals (or triangles with
// quads = 0): inner radius a, outer radius b, the quarter x >= 0, y >= 0.
// Boundaries: inner (r = a), outer (r = b), x_axis (y = 0: symmetry, hold y), y_axis (x = 0:
// symmetry, hold x). Body: wall. The arcs are meshed as straight segments between nodes on the circles.
DefineConstant[ a = {10, Name "Parameters/a", Help "inner radius"} ];
DefineConstant[ b = {20, Name "Parameters/b", Help "outer radius"} ];
DefineConstant[ nr = {4, Name "Parameters/nr", Help "cells through the wall"} ];
DefineConstant[ nc = {8, Name "Parameters/nc", Help "cells around the quarter"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (a <= 0 || b <= a || nr < 1 || nc < 1)
  Error("thick_cylinder_2d.geo: need 0 < a < b, nr >= 1 and nc >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nr + 1; Transfinite Curve{2, 4} = nc + 1;
Transfinite Surface{1};
If (quads) Recombine Surface{1}; EndIf
Physical Curve("x_axis") = {1}; Physical Curve("outer") = {2};
Physical Curve("y_axis") = {3}; Physical Curve("inner") = {4};
Physical Surface("wall") = {1};
