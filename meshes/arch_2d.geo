// Shallow circular arch, 2D, structured quadrilaterals: span S, rise h (centre line), thickness t,
// both ends radial cuts. Boundaries: left, right (the end cuts), apex (a short piece of the top
// surface at the crown), top, bottom. Body: body.
DefineConstant[ S = {100, Name "Parameters/S", Help "span of the centre line"} ];
DefineConstant[ h = {5, Name "Parameters/h", Help "rise of the centre line"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness"} ];
DefineConstant[ n = {40, Name "Parameters/n", Help "cells along each half of the arch"} ];
DefineConstant[ nt = {2, Name "Parameters/nt", Help "cells through the thickness"} ];
DefineConstant[ apex = {0.02, Name "Parameters/apex", Help "half-angle of the loaded crown piece (rad)"} ];
If (S <= 0 || h <= 0 || h > S / 2 || t <= 0 || t * h >= S * S / 4 + h * h ||
    n < 1 || nt < 1 || apex <= 0 || apex >= Asin(S * h / (S * S / 4 + h * h)))
  Error("arch_2d.geo: need S > 0, 0 < h <= S/2, 0 < t < 2 R (R = (S^2/4 + h^2) / (2 h), the radius of the centre line), 0 < apex < the half-angle Asin(S / (2 R)) of the arch, n >= 1 and nt >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
R = (S * S / 4 + h * h) / (2 * h);
beta = Asin(S / (2 * R));
Point(1) = {0, h - R, 0};
angles[] = {-beta, -apex, apex, beta};
For i In {0:3}
  Point(10 + i) = {(R - t/2) * Sin(angles[i]), h - R + (R - t/2) * Cos(angles[i]), 0};
  Point(20 + i) = {(R + t/2) * Sin(angles[i]), h - R + (R + t/2) * Cos(angles[i]), 0};
  Line(30 + i) = {10 + i, 20 + i};
  Transfinite Curve{30 + i} = nt + 1;
EndFor
For i In {0:2}
  Circle(40 + i) = {10 + i, 1, 11 + i};
  Circle(50 + i) = {20 + i, 1, 21 + i};
  cells = (i == 1) ? 2 : n;
  Transfinite Curve{40 + i, 50 + i} = cells + 1;
  Curve Loop(60 + i) = {40 + i, 31 + i, -(50 + i), -(30 + i)};
  Plane Surface(60 + i) = {60 + i};
  Transfinite Surface{60 + i}; Recombine Surface{60 + i};
EndFor
Physical Curve("left") = {30};
Physical Curve("right") = {33};
Physical Curve("apex") = {51};
Physical Curve("top") = {50, 52};
Physical Curve("bottom") = {40, 41, 42};
Physical Surface("body") = {60, 61, 62};
