// Quarter of a square plate with a central elliptical hole, 2D, structured quadrilaterals (or
// triangles with quads = 0): half axes a (along x) and b (along y), plate half width w (x and y
// in [0, w]). The quarter is two blocks split by the line from the ellipse's 45-degree parameter
// point to the corner (w, w); nc cells along the quarter ellipse, nr cells from the hole to the
// edge, each growing by the same factor so that the last is `ratio` times the first.
// Boundaries: hole (the ellipse, gmsh Ellipse curves), x_axis (y = 0: symmetry, hold y), y_axis
// (x = 0: symmetry, hold x), top (y = w: the load), right (x = w: free). Body: plate.
DefineConstant[ a = {2, Name "Parameters/a", Help "half axis of the hole along x"} ];
DefineConstant[ b = {1, Name "Parameters/b", Help "half axis of the hole along y"} ];
DefineConstant[ w = {20, Name "Parameters/w", Help "half width of the square plate"} ];
DefineConstant[ nc = {6, Name "Parameters/nc", Help "cells along the quarter ellipse (even)"} ];
DefineConstant[ nr = {4, Name "Parameters/nr", Help "cells from the hole to the plate's edge"} ];
DefineConstant[ ratio = {8, Name "Parameters/ratio", Help "last radial cell over the first"} ];
DefineConstant[ tip = {1, Name "Parameters/tip", Help "on the arc from the major axis: last cell over the first"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (a <= 0 || b <= 0 || w <= 1.5 * a || w <= 1.5 * b || nc < 2 || nc % 2 != 0 || nr < 1 || ratio <= 0 || tip <= 0)
  Error("elliptical_hole_2d.geo: need a, b > 0, w > 1.5 max(a, b), nc >= 2 even, nr >= 1, ratio, tip > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {a * Cos(Pi / 4), b * Sin(Pi / 4), 0}; Point(4) = {0, b, 0};
Point(5) = {w, 0, 0}; Point(6) = {w, w, 0}; Point(7) = {0, w, 0};
// Ellipse(tag) = {start, centre, a point on the major axis, end}.
If (a >= b)
  Ellipse(1) = {2, 1, 2, 3}; Ellipse(2) = {3, 1, 2, 4};
Else
  Ellipse(1) = {2, 1, 4, 3}; Ellipse(2) = {3, 1, 4, 4};
EndIf
Line(3) = {2, 5}; Line(4) = {5, 6}; Line(5) = {3, 6}; Line(6) = {6, 7}; Line(7) = {4, 7};
Curve Loop(1) = {3, 4, -5, -1}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, -7, -2}; Plane Surface(2) = {2};
growth = nr > 1 ? ratio^(1 / (nr - 1)) : 1;
arc_growth = nc > 2 ? tip^(1 / (nc / 2 - 1)) : 1;
Transfinite Curve{2, 4, 6} = nc / 2 + 1; Transfinite Curve{1} = nc / 2 + 1 Using Progression arc_growth;
Transfinite Curve{3, 5, 7} = nr + 1 Using Progression growth;
Transfinite Surface{1} = {2, 5, 6, 3}; Transfinite Surface{2} = {3, 6, 7, 4};
If (quads) Recombine Surface{1, 2}; EndIf
Physical Curve("hole") = {1, 2}; Physical Curve("x_axis") = {3}; Physical Curve("right") = {4};
Physical Curve("top") = {6}; Physical Curve("y_axis") = {7};
Physical Surface("plate") = {1, 2};
