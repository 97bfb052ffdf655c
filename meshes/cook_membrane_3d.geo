// Cook's membrane as a slab (deal.II code gallery set-up): trapezoid (0,0), (48,44), (48,60), (0,44)
// extruded to z in [-t/2, t/2] with one layer of hexahedra through the thickness.
// Boundaries: left (clamped face), right (loaded face), top, bottom, faces (z = -t/2 and z = +t/2).
// Body: body.
DefineConstant[ n = {8, Name "Parameters/n", Help "elements per side of the trapezoid"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "slab thickness along z (mm)"} ];
If (n < 1 || t <= 0)
  Error("cook_membrane_3d.geo: need n >= 1 and t > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, -t/2}; Point(2) = {48, 44, -t/2}; Point(3) = {48, 60, -t/2}; Point(4) = {0, 44, -t/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n + 1;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, t} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("bottom") = {out[2]}; Physical Surface("right") = {out[3]};
Physical Surface("top") = {out[4]}; Physical Surface("left") = {out[5]};
Physical Surface("faces") = {1, out[0]};
Physical Volume("body") = {out[1]};
