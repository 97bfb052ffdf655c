// Cook's membrane (Cook 1974): trapezoid (0,0), (48,44), (48,60), (0,44), structured quadrilaterals.
// Boundaries: left (clamped edge), right (loaded edge), top, bottom. Body: body.
DefineConstant[ n = {8, Name "Parameters/n", Help "elements per side"} ];
If (n < 1)
  Error("cook_membrane.geo: need n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0}; Point(2) = {48, 44, 0}; Point(3) = {48, 60, 0}; Point(4) = {0, 44, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1}; Recombine Surface{1};
Physical Curve("bottom") = {1}; Physical Curve("right") = {2};
Physical Curve("top") = {3}; Physical Curve("left") = {4};
Physical Surface("body") = {1};
