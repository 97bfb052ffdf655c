// Quarter of a thick-walled cylinder (Lame) of length h, 3D: the quarter annulus of
// thick_cylinder_2d.geo extruded along z, hexahedra (quads = 1) or tetrahedra (quads = 0).
// Boundaries: inner (r = a), outer (r = b), x_axis (y = 0), y_axis (x = 0), bottom (z = 0),
// top (z = h). Body: wall. Holding z on bottom and top gives plane strain, the 2D Lame solution.
DefineConstant[ a = {10, Name "Parameters/a", Help "inner radius"} ];
DefineConstant[ b = {20, Name "Parameters/b", Help "outer radius"} ];
DefineConstant[ h = {5, Name "Parameters/h", Help "length along the axis"} ];
DefineConstant[ nr = {2, Name "Parameters/nr", Help "cells through the wall"} ];
DefineConstant[ nc = {4, Name "Parameters/nc", Help "cells around the quarter"} ];
DefineConstant[ nz = {1, Name "Parameters/nz", Help "cells along the axis (hexahedra)"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: hexahedra, 0: tetrahedra"} ];
If (a <= 0 || b <= a || h <= 0 || nr < 1 || nc < 1 || nz < 1)
  Error("thick_cylinder_3d.geo: need 0 < a < b, h > 0, nr, nc, nz >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
If (quads)
  Transfinite Curve{1, 3} = nr + 1; Transfinite Curve{2, 4} = nc + 1;
  Transfinite Surface{1}; Recombine Surface{1};
  out[] = Extrude {0, 0, h} { Surface{1}; Layers{nz}; Recombine; };
Else
  Mesh.MeshSizeMax = (b - a) / nr;
  out[] = Extrude {0, 0, h} { Surface{1}; };
EndIf
Physical Surface("bottom") = {1}; Physical Surface("top") = {out[0]};
Physical Surface("x_axis") = {out[2]}; Physical Surface("outer") = {out[3]};
Physical Surface("y_axis") = {out[4]}; Physical Surface("inner") = {out[5]};
Physical Volume("wall") = {out[1]};
