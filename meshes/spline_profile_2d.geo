// A bar of length L and height h whose top edge has a smooth notch of depth d shaped by a cubic
// BSpline, and whose bottom edge is a shallow Catmull-Rom Spline through given points: curved
// boundaries that are no circles (the solver follows them through samples of gmsh's curves).
// Quadrilaterals (quads = 1, recombined) or triangles, size lc.
// Boundaries: left (x = 0), right (x = L), notch (the top BSpline), bottom (the Spline). Body: bar.
DefineConstant[ L = {10, Name "Parameters/L", Help "length"} ];
DefineConstant[ h = {2, Name "Parameters/h", Help "height"} ];
DefineConstant[ d = {0.6, Name "Parameters/d", Help "depth of the notch"} ];
DefineConstant[ lc = {0.5, Name "Parameters/lc", Help "mesh size"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (L <= 0 || h <= 0 || d < 0 || d >= h / 2 || lc <= 0)
  Error("spline_profile_2d.geo: need L, h, lc > 0 and 0 <= d < h/2");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0, lc}; Point(2) = {L, 0, 0, lc}; Point(3) = {L, h, 0, lc}; Point(4) = {0, h, 0, lc};
// BSpline control points of the notch (the curve passes through the end points only).
Point(10) = {0.7 * L, h, 0, lc}; Point(11) = {0.55 * L, h - d, 0, lc}; Point(12) = {0.45 * L, h - d, 0, lc};
Point(13) = {0.3 * L, h, 0, lc};
// Points the bottom Spline passes through.
Point(20) = {0.25 * L, -0.05 * h, 0, lc}; Point(21) = {0.5 * L, 0.05 * h, 0, lc}; Point(22) = {0.75 * L, -0.05 * h, 0, lc};
Spline(1) = {1, 20, 21, 22, 2}; Line(2) = {2, 3}; BSpline(3) = {3, 10, 11, 12, 13, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
If (quads) Recombine Surface{1}; EndIf
Physical Curve("bottom") = {1}; Physical Curve("right") = {2}; Physical Curve("notch") = {3};
Physical Curve("left") = {4};
Physical Surface("bar") = {1};
