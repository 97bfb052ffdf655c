// A one-piece fork, 2D: two prongs of length L and height h, a slot of width g between them, joined
// by a root block of length a whose left face (root) is held. The upper prong bent down closes the
// slot onto the lower one: the part touches itself. Structured quadrilaterals: nx cells along the
// prongs, na along the root, ny through each prong, one across the slot.
// Boundaries: root (x = -a), lower_top (the lower prong's face along the slot), upper_bottom (the
// upper prong's face along it), upper_tip and lower_tip (x = L), slot_end (x = 0 between the
// prongs), outer (the rest). Body: fork.
DefineConstant[ L = {20, Name "Parameters/L", Help "prong length"} ];
DefineConstant[ h = {1, Name "Parameters/h", Help "prong height"} ];
DefineConstant[ g = {0.32, Name "Parameters/g", Help "slot width"} ];
DefineConstant[ a = {2, Name "Parameters/a", Help "root length"} ];
DefineConstant[ nx = {40, Name "Parameters/nx", Help "cells along a prong"} ];
DefineConstant[ ny = {2, Name "Parameters/ny", Help "cells through a prong"} ];
DefineConstant[ na = {4, Name "Parameters/na", Help "cells along the root"} ];
If (L <= 0 || h <= 0 || g <= 0 || a <= 0 || nx < 1 || ny < 1 || na < 1)
  Error("fork_2d.geo: need L, h, g, a > 0 and nx, ny, na >= 1");
  Abort;
EndIf
Point(1) = {-a, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {L, 0, 0}; Point(4) = {L, h, 0};
Point(5) = {0, h, 0}; Point(6) = {-a, h, 0}; Point(7) = {-a, h + g, 0}; Point(8) = {0, h + g, 0};
Point(9) = {L, h + g, 0}; Point(10) = {L, 2 * h + g, 0}; Point(11) = {0, 2 * h + g, 0};
Point(12) = {-a, 2 * h + g, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 6};
Line(6) = {6, 1}; Line(7) = {2, 5}; Line(8) = {5, 8}; Line(9) = {8, 7}; Line(10) = {7, 6};
Line(11) = {8, 9}; Line(12) = {9, 10}; Line(13) = {10, 11}; Line(14) = {11, 8}; Line(15) = {11, 12};
Line(16) = {12, 7};
Curve Loop(1) = {1, 7, 5, 6}; Plane Surface(1) = {1};         // root, lower strip
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};        // lower prong
Curve Loop(3) = {-5, 8, 9, 10}; Plane Surface(3) = {3};       // root, across the slot
Curve Loop(4) = {-9, -14, 15, 16}; Plane Surface(4) = {4};    // root, upper strip
Curve Loop(5) = {11, 12, 13, 14}; Plane Surface(5) = {5};     // upper prong
Transfinite Curve{2, 4, 11, 13} = nx + 1; Transfinite Curve{1, 5, 9, 15} = na + 1;
Transfinite Curve{3, 7, 6, 12, 14, 16} = ny + 1; Transfinite Curve{8, 10} = 2;
Transfinite Surface{1:5}; Recombine Surface{1:5};
Physical Curve("root") = {6, 10, 16}; Physical Curve("lower_top") = {4};
Physical Curve("upper_bottom") = {11}; Physical Curve("upper_tip") = {12}; Physical Curve("lower_tip") = {3};
Physical Curve("slot_end") = {8}; Physical Curve("outer") = {1, 2, 13, 15};
Physical Surface("fork") = {1:5};
