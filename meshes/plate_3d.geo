// Rectangular plate, 3D, structured hexahedra: x in [0, a], y in [0, b], z in [-t/2, t/2].
// Boundaries: bottom (z = -t/2), top (z = t/2), x_ends (x = 0, a), y_ends (y = 0, b). Body: plate.
// Edges are where two boundaries meet, e.g. 'bottom & x_ends' for two edges of the bottom face.
DefineConstant[ a = {10, Name "Parameters/a", Help "length along x"} ];
DefineConstant[ b = {10, Name "Parameters/b", Help "width along y"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness along z"} ];
DefineConstant[ nx = {8, Name "Parameters/nx", Help "elements along x"} ];
DefineConstant[ ny = {8, Name "Parameters/ny", Help "elements along y"} ];
DefineConstant[ nz = {2, Name "Parameters/nz", Help "elements through the thickness"} ];
If (a <= 0 || b <= 0 || t <= 0 || nx < 1 || ny < 1 || nz < 1)
  Error("plate_3d.geo: need a, b, t > 0 and nx, ny, nz >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, -t/2}; Point(2) = {a, 0, -t/2}; Point(3) = {a, b, -t/2}; Point(4) = {0, b, -t/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1; Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, t} { Surface{1}; Layers{nz}; Recombine; };
Physical Surface("bottom") = {1};
Physical Surface("top") = {out[0]};
// Extrude numbers the lateral faces after the curves 1-4: y = 0, x = a, y = b, x = 0.
Physical Surface("y_ends") = {out[2], out[4]};
Physical Surface("x_ends") = {out[3], out[5]};
Physical Volume("plate") = {out[1]};
