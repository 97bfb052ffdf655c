// Circular tube (outer radius R, inner radius r) for section_torsion: a section with a hole, whose
// exact solution is omega = 0, J = pi (R^4 - r^4) / 2 and tau_max = T R / J on the outer
// surface. The boundary circles become polygons through the gmsh nodes (facet error ~ h^2).
// Cells: unstructured triangles of size (R - r) / n. Boundary: boundary (both circles). Body: section.
DefineConstant[ R = {10, Name "Parameters/R", Help "outer radius"} ];
DefineConstant[ r = {6, Name "Parameters/r", Help "inner radius"} ];
DefineConstant[ n = {8, Name "Parameters/n", Help "elements through the wall"} ];
If (r <= 0 || R <= r || n < 1)
  Error("section_tube.geo: need 0 < r < R and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, R};
Disk(2) = {0, 0, 0, r};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Mesh.MeshSizeMax = (R - r) / n;
MeshSize{ PointsOf{ Surface{3}; } } = (R - r) / n;
outer() = Abs(Boundary{ Surface{3}; });
Physical Curve("boundary") = {outer()};
Physical Surface("section") = {3};
