// Rectangular bar, 3D, structured hexahedra (or tetrahedra with hexes = 0): x in [0, L], cross-section H (y) x W (z) centred.
// Boundaries: left (x=0), right (x=L), sides. Body: body.
DefineConstant[ L = {100, Name "Parameters/L", Help "length along x"} ];
DefineConstant[ H = {10, Name "Parameters/H", Help "depth along y"} ];
DefineConstant[ W = {10, Name "Parameters/W", Help "width along z"} ];
DefineConstant[ ny = {4, Name "Parameters/ny", Help "elements along y"} ];
DefineConstant[ nz = {4, Name "Parameters/nz", Help "elements along z"} ];
DefineConstant[ hexes = {1, Name "Parameters/hexes", Help "1: structured hexahedra, 0: unstructured tetrahedra"} ];
DefineConstant[ nx = {0, Name "Parameters/nx", Help "elements along x; 0: about square cells (ny L/H)"} ];
DefineConstant[ grade_x = {1, Name "Parameters/grade_x", Help "longest over shortest cell along x, the lengths in geometric progression (1: uniform); resolves the stress singularity and the warping layer at a clamp"} ];
DefineConstant[ graded_ends = {0, Name "Parameters/graded_ends", Help "where the shortest cells along x lie when grade_x > 1: 0 both ends, 1 x = 0, 2 x = L"} ];
If (L <= 0 || H <= 0 || W <= 0 || ny < 1 || nz < 1 || (nx != 0 && nx < 1))
  Error("cantilever_3d.geo: need L, H, W > 0, ny, nz >= 1 and nx >= 1 (or nx = 0: about square cells)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
n_x = (nx > 0) ? nx : Ceil(ny * L / H);
If (grade_x < 1 || (graded_ends != 0 && graded_ends != 1 && graded_ends != 2) || (grade_x > 1 && hexes != 1) ||
    (grade_x > 1 && n_x < ((graded_ends == 0) ? 3 : 2)))
  Error("cantilever_3d.geo: need grade_x >= 1 (hexahedra only), graded_ends 0, 1 or 2, and with grade_x > 1 at least 3 cells along x (2 with one graded end)");
  Abort;
EndIf
Include "graded_layers.geo"; // layer_count[], layer_top[] from n_x, grade_x, graded_ends
Point(1) = {0, -H/2, -W/2}; Point(2) = {0, H/2, -W/2}; Point(3) = {0, H/2, W/2}; Point(4) = {0, -H/2, W/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = ny + 1; Transfinite Curve{2, 4} = nz + 1;
If (hexes)
  Transfinite Surface{1}; Recombine Surface{1};
  If (grade_x > 1)
    out[] = Extrude {L, 0, 0} { Surface{1}; Layers{layer_count[], layer_top[]}; Recombine; };
  Else
    out[] = Extrude {L, 0, 0} { Surface{1}; Layers{n_x}; Recombine; };
  EndIf
Else
  out[] = Extrude {L, 0, 0} { Surface{1}; };
  Mesh.CharacteristicLengthMax = H / ny;
EndIf
Physical Surface("left") = {1};
Physical Surface("right") = {out[0]};
Physical Surface("sides") = {out[2], out[3], out[4], out[5]};
Physical Volume("body") = {out[1]};
