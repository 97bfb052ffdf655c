// Solid rectangular cross-section a x b (Saint-Venant torsion, section_torsion), side a along the
// local x axis, centred at (x0, y0) and turned by `angle` degrees; the solver finds the centroid and
// the shear centre itself, so the offset and the turn only test that.
// Cells: structured quadrilaterals (quads = 1) or unstructured triangles (quads = 0), about square,
// n across the shorter side. Boundary: boundary. Body: section.
DefineConstant[ a = {100, Name "Parameters/a", Help "side along the local x axis"} ];
DefineConstant[ b = {50, Name "Parameters/b", Help "side along the local y axis"} ];
DefineConstant[ n = {8, Name "Parameters/n", Help "elements across the shorter side"} ];
DefineConstant[ quads = {1, Name "Parameters/quads", Help "1: structured quadrilaterals, 0: unstructured triangles"} ];
DefineConstant[ angle = {0, Name "Parameters/angle", Help "turn of the section about its centre (degrees)"} ];
DefineConstant[ x0 = {0, Name "Parameters/x0", Help "x of the centre"} ];
DefineConstant[ y0 = {0, Name "Parameters/y0", Help "y of the centre"} ];
If (a <= 0 || b <= 0 || n < 1)
  Error("section_rectangle.geo: need a > 0, b > 0 and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
h = (a < b ? a : b) / n;
c = Cos(angle * Pi / 180); s = Sin(angle * Pi / 180);
xs[] = {-a/2, a/2, a/2, -a/2};
ys[] = {-b/2, -b/2, b/2, b/2};
For i In {0:3}
  Point(i + 1) = {x0 + c * xs[i] - s * ys[i], y0 + s * xs[i] + c * ys[i], 0, h};
EndFor
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
If (quads)
  Transfinite Curve{1, 3} = Ceil(a / h - 1e-9) + 1;
  Transfinite Curve{2, 4} = Ceil(b / h - 1e-9) + 1;
  Transfinite Surface{1}; Recombine Surface{1};
EndIf
Physical Curve("boundary") = {1, 2, 3, 4};
Physical Surface("section") = {1};
