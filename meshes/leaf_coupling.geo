// The elastic coupling of the variable-stiffness servo (seed 002), 3D, structured hexahedra:
// four leaf springs parallel to the shaft axis z, from the gear (z = 0) to the shaft (z = L),
// centred at radius r, 90 degrees apart, the width a radial and the thickness b tangential
// (the orientation that makes the paper's stiffness grow linearly with a; see
// cases/leaf_spring/README.md). The discs are rigid: the case clamps the gear ends and turns
// the shaft ends rigidly about z.
// Boundaries: gear (the four ends at z = 0), shaft (the four ends at z = L), sides. Body: leaves.
DefineConstant[ L = {5, Name "Parameters/L", Help "active (clutch) length of the leaves"} ];
DefineConstant[ a = {4, Name "Parameters/a", Help "width of a leaf (radial)"} ];
DefineConstant[ b = {0.5, Name "Parameters/b", Help "thickness of a leaf (tangential)"} ];
DefineConstant[ r = {8, Name "Parameters/r", Help "radius of the leaves' centres; not given by the paper (8 mm: see cases/leaf_spring/README.md)"} ];
DefineConstant[ nb = {2, Name "Parameters/nb", Help "elements through the thickness b"} ];
DefineConstant[ na = {0, Name "Parameters/na", Help "elements across the width a; 0: square cells (nb a / b)"} ];
DefineConstant[ nL = {0, Name "Parameters/nL", Help "elements along L; 0: square cells (nb L / b)"} ];
If (L <= 0 || a <= 0 || b <= 0 || nb < 1 || (na != 0 && na < 1) || (nL != 0 && nL < 1) || r <= (a + b) / 2)
  Error("leaf_coupling.geo: need L, a, b > 0, r > (a + b)/2 (neighbouring leaves apart), nb >= 1, na and nL >= 1 (or 0: square cells)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
If (r <= a/2 || 2 * r * Sin(Pi/4) <= a)
  Error("leaf_coupling.geo: r = %g must exceed a/2 and keep neighbouring leaves apart (a = %g)", r, a);
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
n_a = (na > 0) ? na : Ceil(nb * a / b);
n_L = (nL > 0) ? nL : Ceil(nb * L / b);
gear[] = {}; shaft[] = {}; sides[] = {}; leaves[] = {};
For i In {0:3}
  phi = i * Pi / 2;
  cr = Cos(phi); sr = Sin(phi);   // radial unit vector (cr, sr); tangential (-sr, cr)
  p1 = newp; Point(p1) = {(r - a/2) * cr + b/2 * sr, (r - a/2) * sr - b/2 * cr, 0};
  p2 = newp; Point(p2) = {(r + a/2) * cr + b/2 * sr, (r + a/2) * sr - b/2 * cr, 0};
  p3 = newp; Point(p3) = {(r + a/2) * cr - b/2 * sr, (r + a/2) * sr + b/2 * cr, 0};
  p4 = newp; Point(p4) = {(r - a/2) * cr - b/2 * sr, (r - a/2) * sr + b/2 * cr, 0};
  l1 = newl; Line(l1) = {p1, p2};
  l2 = newl; Line(l2) = {p2, p3};
  l3 = newl; Line(l3) = {p3, p4};
  l4 = newl; Line(l4) = {p4, p1};
  cl = newll; Curve Loop(cl) = {l1, l2, l3, l4};
  s = news; Plane Surface(s) = {cl};
  Transfinite Curve{l1, l3} = n_a + 1; Transfinite Curve{l2, l4} = nb + 1;
  Transfinite Surface{s}; Recombine Surface{s};
  out[] = Extrude {0, 0, L} { Surface{s}; Layers{n_L}; Recombine; };
  gear[] += {s}; shaft[] += {out[0]}; leaves[] += {out[1]}; sides[] += {out[{2:5}]};
EndFor
Physical Surface("gear") = {gear[]};
Physical Surface("shaft") = {shaft[]};
Physical Surface("sides") = {sides[]};
Physical Volume("leaves") = {leaves[]};
