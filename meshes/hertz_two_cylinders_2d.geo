// Two equal elastic cylinders pressed together, 2D: the quarter discs of radius R centred at
// (0, R) and (0, -R), touching at the origin but meshed apart (their nodes are not shared), cut
// by the symmetry line x = 0 and by the horizontal diameters y = R and y = -R. Unstructured
// quadrilaterals graded from b/nb within 2b of the contact point to R/nf far from it; the lower
// disc is meshed on its own, not mirrored, so the two arcs' nodes need not match.
// Boundaries: upper_arc, lower_arc (the circles), upper_sym, lower_sym (x = 0), top (y = R),
// bottom (y = -R). Bodies: upper, lower.
DefineConstant[ R = {10, Name "Parameters/R", Help "cylinder radius"} ];
DefineConstant[ b = {0.1, Name "Parameters/b", Help "expected contact half-width (size of the fine zone)"} ];
DefineConstant[ nb = {20, Name "Parameters/nb", Help "cells across the half-width b"} ];
DefineConstant[ nf = {10, Name "Parameters/nf", Help "cells along R far from the contact"} ];
If (R <= 0 || b <= 0 || b >= R / 4 || nb < 1 || nf < 1)
  Error("hertz_two_cylinders_2d.geo: need R > 0, 0 < b < R/4, nb >= 1 and nf >= 1");
  Abort;
EndIf
Geometry.AutoCoherence = 0; // the two discs' touching points must stay apart
Point(1) = {0, 0, 0}; Point(2) = {0, R, 0}; Point(3) = {R, R, 0};
Circle(1) = {1, 2, 3}; Line(2) = {3, 2}; Line(3) = {2, 1};
Curve Loop(1) = {1, 2, 3}; Plane Surface(1) = {1};
Point(4) = {0, 0, 0}; Point(5) = {0, -R, 0}; Point(6) = {R, -R, 0};
Circle(4) = {4, 5, 6}; Line(5) = {6, 5}; Line(6) = {5, 4};
Curve Loop(2) = {4, 5, 6}; Plane Surface(2) = {2};
Field[1] = Distance; Field[1].NodesList = {1, 4};
Field[2] = Threshold; Field[2].IField = 1;
Field[2].LcMin = b / nb; Field[2].LcMax = R / nf;
Field[2].DistMin = 2 * b; Field[2].DistMax = R / 2;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6;
Mesh.RecombinationAlgorithm = 3;
Recombine Surface{1, 2};
Physical Curve("upper_arc") = {1}; Physical Curve("top") = {2}; Physical Curve("upper_sym") = {3};
Physical Curve("lower_arc") = {4}; Physical Curve("bottom") = {5}; Physical Curve("lower_sym") = {6};
Physical Surface("upper") = {1}; Physical Surface("lower") = {2};
