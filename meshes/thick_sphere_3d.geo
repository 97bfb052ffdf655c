// Octant of a thick-walled sphere (Lame): inner radius a, outer radius b, tetrahedra of size lc
// (OpenCASCADE). Boundaries: inner (r = a), outer (r = b), x_sym, y_sym, z_sym (the coordinate
// planes: hold the normal component). Body: shell.
SetFactory("OpenCASCADE");
DefineConstant[ a = {10, Name "Parameters/a", Help "inner radius"} ];
DefineConstant[ b = {20, Name "Parameters/b", Help "outer radius"} ];
DefineConstant[ lc = {5, Name "Parameters/lc", Help "tetrahedron size"} ];
If (a <= 0 || b <= a || lc <= 0)
  Error("thick_sphere_3d.geo: need 0 < a < b and lc > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Sphere(1) = {0, 0, 0, b};
Sphere(2) = {0, 0, 0, a};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(4) = {0, 0, 0, b, b, b};
BooleanIntersection(5) = { Volume{3}; Delete; }{ Volume{4}; Delete; };
e = 1e-3 * a;
x_sym[] = Surface In BoundingBox{-e, -e, -e, e, b + e, b + e};
y_sym[] = Surface In BoundingBox{-e, -e, -e, b + e, e, b + e};
z_sym[] = Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
inner[] = Surface In BoundingBox{-e, -e, -e, a + e, a + e, a + e};
outer[] = Surface In BoundingBox{-e, -e, -e, b + e, b + e, b + e};
outer[] -= {x_sym[], y_sym[], z_sym[], inner[]};
Physical Surface("x_sym") = {x_sym[]}; Physical Surface("y_sym") = {y_sym[]};
Physical Surface("z_sym") = {z_sym[]}; Physical Surface("inner") = {inner[]};
Physical Surface("outer") = {outer[]};
Physical Volume("shell") = {5};
Mesh.MeshSizeMax = lc;
