// Hertz contact of a cylinder on a rigid plane, 2D: the quarter of a disc of radius R whose
// lowest point touches the plane y = 0 at the origin (centre at (0, R)), cut by its vertical
// symmetry line x = 0 and its horizontal diameter y = R (loaded there). Unstructured
// quadrilaterals graded from b/nb within 2b of the contact point (b: the expected contact
// half-width) to R/nf far from it.
// Boundaries: arc (the circle, which touches the plane), sym (x = 0), top (y = R). Body: disc.
DefineConstant[ R = {10, Name "Parameters/R", Help "cylinder radius"} ];
DefineConstant[ b = {0.1, Name "Parameters/b", Help "expected contact half-width (size of the fine zone)"} ];
DefineConstant[ nb = {20, Name "Parameters/nb", Help "cells across the half-width b"} ];
DefineConstant[ nf = {10, Name "Parameters/nf", Help "cells along R far from the contact"} ];
If (R <= 0 || b <= 0 || b >= R / 4 || nb < 1 || nf < 1)
  Error("hertz_cylinder_2d.geo: need R > 0, 0 < b < R/4, nb >= 1 and nf >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0}; Point(2) = {0, R, 0}; Point(3) = {R, R, 0};
Circle(1) = {1, 2, 3}; Line(2) = {3, 2}; Line(3) = {2, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
// Blossom full-quad recombination of a frontal-Delaunay mesh: quadrilaterals only.
Field[1] = Distance; Field[1].NodesList = {1};
Field[2] = Threshold; Field[2].IField = 1;
Field[2].LcMin = b / nb; Field[2].LcMax = R / nf;
Field[2].DistMin = 2 * b; Field[2].DistMax = R / 2;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6;               // frontal-Delaunay + blossom recombination
Mesh.RecombinationAlgorithm = 3;  // blossom full-quad: no triangle left over
Recombine Surface{1};
Physical Curve("arc") = {1}; Physical Curve("top") = {2}; Physical Curve("sym") = {3};
Physical Surface("disc") = {1};
