// One leaf spring of the variable-stiffness servo (seed 002), 3D, structured hexahedra.
// Axis along x in [0, L]; width a along y and thickness b along z, both centred on the axis,
// so bending in the thin direction (the servo's, see cases/leaf_spring/README.md) moves z.
// Boundaries: gear (x = 0), shaft (x = L), sides. Body: leaf.
DefineConstant[ L = {5, Name "Parameters/L", Help "active (clutch) length of the leaf"} ];
DefineConstant[ a = {4, Name "Parameters/a", Help "width of the leaf (along y)"} ];
DefineConstant[ b = {0.5, Name "Parameters/b", Help "thickness of the leaf (along z)"} ];
DefineConstant[ nb = {2, Name "Parameters/nb", Help "elements through the thickness b"} ];
DefineConstant[ na = {0, Name "Parameters/na", Help "elements across the width a; 0: square cells (nb a / b)"} ];
DefineConstant[ aspect = {1, Name "Parameters/aspect", Help "length of a cell along the axis over b / nb (long leaves: up to about 8)"} ];
DefineConstant[ nL = {0, Name "Parameters/nL", Help "elements along L; 0: from aspect"} ];
If (L <= 0 || a <= 0 || b <= 0 || nb < 1 || (na != 0 && na < 1) || aspect <= 0 || (nL != 0 && nL < 1))
  Error("leaf_spring.geo: need L, a, b > 0, nb >= 1, aspect > 0, na and nL >= 1 (or 0: automatic)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
n_a = (na > 0) ? na : Ceil(nb * a / b);
n_L = (nL > 0) ? nL : Ceil(nb * L / (b * aspect));
Point(1) = {0, -a/2, -b/2}; Point(2) = {0, a/2, -b/2}; Point(3) = {0, a/2, b/2}; Point(4) = {0, -a/2, b/2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 3} = n_a + 1; Transfinite Curve{2, 4} = nb + 1;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {L, 0, 0} { Surface{1}; Layers{n_L}; Recombine; };
Physical Surface("gear") = {1};
Physical Surface("shaft") = {out[0]};
Physical Surface("sides") = {out[2], out[3], out[4], out[5]};
Physical Volume("leaf") = {out[1]};
