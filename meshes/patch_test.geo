// MacNeal-Harder patch (Finite Elem. Anal. Des. 1, 1985): a 0.24 x 0.12 rectangle cut into five
// distorted quadrilaterals. With Parameters/extrude > 0 the patch is extruded into distorted
// hexahedra (3D). Boundaries: left, right, bottom, top (and front, back in 3D). Body: body.
DefineConstant[ extrude = {0, Name "Parameters/extrude", Help "thickness of the 3D extrusion; 0 keeps the patch 2D"} ];
DefineConstant[ shear = {0.01, Name "Parameters/shear", Help "extra skew of the extruded top face (3D only), to distort the hexahedra"} ];
If (extrude < 0)
  Error("patch_test.geo: need extrude >= 0 (0: the 2D patch, > 0: the thickness of the 3D one)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
Point(1) = {0, 0, 0}; Point(2) = {0.24, 0, 0}; Point(3) = {0.24, 0.12, 0}; Point(4) = {0, 0.12, 0};
Point(5) = {0.04, 0.02, 0}; Point(6) = {0.18, 0.03, 0}; Point(7) = {0.16, 0.08, 0}; Point(8) = {0.08, 0.08, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 10, -5, -9}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 11, -6, -10}; Plane Surface(2) = {2};
Curve Loop(3) = {3, 12, -7, -11}; Plane Surface(3) = {3};
Curve Loop(4) = {4, 9, -8, -12}; Plane Surface(4) = {4};
Curve Loop(5) = {5, 6, 7, 8}; Plane Surface(5) = {5};
Transfinite Curve{1:12} = 2;
Transfinite Surface{1:5}; Recombine Surface{1:5};
If (extrude == 0)
  Physical Curve("bottom") = {1}; Physical Curve("right") = {2};
  Physical Curve("top") = {3}; Physical Curve("left") = {4};
  Physical Surface("body") = {1:5};
Else
  For s In {1:5}
    out[] = Extrude {shear, 0, extrude} { Surface{s}; Layers{1}; Recombine; };
    vol[] += {out[1]}; top[] += {out[0]};
    If (s <= 4) side[s] = out[2]; EndIf
  EndFor
  Physical Surface("bottom") = {side[1]}; Physical Surface("right") = {side[2]};
  Physical Surface("top") = {side[3]}; Physical Surface("left") = {side[4]};
  Physical Surface("back") = {1:5}; Physical Surface("front") = {top[]};
  Physical Volume("body") = {vol[]};
EndIf
