// Quarter of a square plate with a central elliptical hole, 3D: meshes/elliptical_hole_2d.geo's
// quarter (half axes a, b, half width w, nc cells along the quarter ellipse, nr from the hole to
// the edge) extruded by the thickness t in nz layers of hexahedra (z in [0, t]). The hole's two
// faces are extrusions of ellipse arcs: curved, but neither cylinders nor spheres.
// Boundaries: hole, x_axis (y = 0), y_axis (x = 0), top (y = w), right (x = w), bottom (z = 0),
// front (z = t). Body: plate.
DefineConstant[ a = {2, Name "Parameters/a", Help "half axis of the hole along x"} ];
DefineConstant[ b = {1, Name "Parameters/b", Help "half axis of the hole along y"} ];
DefineConstant[ w = {20, Name "Parameters/w", Help "half width of the square plate"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness"} ];
DefineConstant[ nc = {6, Name "Parameters/nc", Help "cells along the quarter ellipse (even)"} ];
DefineConstant[ nr = {4, Name "Parameters/nr", Help "cells from the hole to the plate's edge"} ];
DefineConstant[ nz = {1, Name "Parameters/nz", Help "layers of cells through the thickness"} ];
DefineConstant[ ratio = {8, Name "Parameters/ratio", Help "last radial cell over the first"} ];
DefineConstant[ tip = {1, Name "Parameters/tip", Help "on the arc from the major axis: last cell over the first"} ];
If (a <= 0 || b <= 0 || t <= 0 || w <= 1.5 * a || w <= 1.5 * b || nc < 2 || nc % 2 != 0 || nr < 1 || nz < 1 || ratio <= 0 || tip <= 0)
  Error("elliptical_hole_3d.geo: need a, b, t > 0, w > 1.5 max(a, b), nc >= 2 even, nr, nz >= 1, ratio, tip > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {a * Cos(Pi / 4), b * Sin(Pi / 4), 0}; Point(4) = {0, b, 0};
Point(5) = {w, 0, 0}; Point(6) = {w, w, 0}; Point(7) = {0, w, 0};
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
Recombine Surface{1, 2};
// Extrude numbers the lateral faces after the loop's curves: out[2..5] for loop 1's {3, 4, -5,
// -1}, then out[8..11] for loop 2's {5, 6, -7, -2}.
one[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
two[] = Extrude {0, 0, t} { Surface{2}; Layers{nz}; Recombine; };
Physical Surface("bottom") = {1, 2};
Physical Surface("front") = {one[0], two[0]};
Physical Surface("x_axis") = {one[2]}; Physical Surface("right") = {one[3]};
Physical Surface("hole") = {one[5], two[5]};
Physical Surface("top") = {two[3]}; Physical Surface("y_axis") = {two[4]};
Physical Volume("plate") = {one[1], two[1]};
