// A quarter of a rectangular plate a x b x t, 3D, structured hexahedra, for the modes symmetric
// about both mid-lines: x in [0, a/2], y in [0, b/2], z in [-t/2, t/2].
// Boundaries: edge_x (x = 0) and edge_y (y = 0), edges of the plate; mid_x (x = a/2) and mid_y
// (y = b/2), its symmetry planes; bottom (z = -t/2), top (z = t/2). Body: plate.
DefineConstant[ a = {100, Name "Parameters/a", Help "length of the whole plate along x"} ];
DefineConstant[ b = {100, Name "Parameters/b", Help "width of the whole plate along y"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness along z"} ];
DefineConstant[ nx = {8, Name "Parameters/nx", Help "elements along x (over a/2)"} ];
DefineConstant[ ny = {8, Name "Parameters/ny", Help "elements along y (over b/2)"} ];
DefineConstant[ nz = {1, Name "Parameters/nz", Help "elements through the thickness"} ];
If (a <= 0 || b <= 0 || t <= 0 || nx < 1 || ny < 1 || nz < 1)
  Error("plate_quarter_3d.geo: need a, b, t > 0 and nx, ny, nz >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, -t/2}; Point(2) = {a/2, 0, -t/2}; Point(3) = {a/2, b/2, -t/2}; Point(4) = {0, b/2, -t/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1; Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
// Extrude numbers the lateral faces after the curves 1-4: y = 0, x = a/2, y = b/2, x = 0.
Physical Surface("edge_y") = {out[2]};
Physical Surface("mid_x") = {out[3]};
Physical Surface("mid_y") = {out[4]};
Physical Surface("edge_x") = {out[5]};
Physical Volume("plate") = {out[1]};
