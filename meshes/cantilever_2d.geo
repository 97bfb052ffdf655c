// Rectangular cantilever, 2D, structured quadrilaterals (or triangles with quads = 0).
// Boundaries: left (x=0), right (x=L), top, bottom. Body: body.
DefineConstant[ L = {100, Name "Parameters/L", Help "length along x"} ];
DefineConstant[ H = {10, Name "Parameters/H", Help "depth along y (bending depth)"} ];
DefineConstant[ ny = {4, Name "Parameters/ny", Help "elements through the depth"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
DefineConstant[ nx = {0, Name "Parameters/nx", Help "elements along the length; 0: square cells (ny L/H)"} ];
If (L <= 0 || H <= 0 || ny < 1 || (nx != 0 && nx < 1))
  Error("cantilever_2d.geo: need L > 0, H > 0, ny >= 1 and nx >= 1 (or nx = 0: square cells)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
n_x = (nx > 0) ? nx : Ceil(ny * L / H);
Point(1) = {0, -H/2, 0}; Point(2) = {L, -H/2, 0}; Point(3) = {L, H/2, 0}; Point(4) = {0, H/2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n_x + 1; Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
If (quads) Recombine Surface{1}; EndIf
Physical Curve("bottom") = {1}; Physical Curve("right") = {2};
Physical Curve("top") = {3}; Physical Curve("left") = {4};
Physical Surface("body") = {1};
