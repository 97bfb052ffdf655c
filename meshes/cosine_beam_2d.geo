// Pre-curved (cosine) clamped-clamped beam, 2D, structured quadrilaterals: span L, centre-line rise
// h, y = h/2 (1 - cos(2 pi x / L)) plus an antisymmetric imperfection of amplitude imp * h
// (sin(2 pi x / L) (1 - cos(2 pi x / L)) / 2: zero with zero slope at both ends), thickness t
// measured vertically (a shallow beam). The bistable element of Qiu, Lang and Slocum's switch.
// Boundaries: left, right (the clamped ends), apex (a piece 2a wide of the top surface at the
// centre), top, bottom. Body: body.
DefineConstant[ L = {100, Name "Parameters/L", Help "span"} ];
DefineConstant[ h = {4, Name "Parameters/h", Help "rise of the centre line"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness (vertical)"} ];
DefineConstant[ imp = {1e-4, Name "Parameters/imp", Help "antisymmetric imperfection, fraction of h"} ];
DefineConstant[ n = {50, Name "Parameters/n", Help "cells along each half of the beam"} ];
DefineConstant[ nt = {2, Name "Parameters/nt", Help "cells through the thickness"} ];
DefineConstant[ a = {1, Name "Parameters/a", Help "half-width of the driven piece at the centre"} ];
If (L <= 0 || t <= 0 || a <= 0 || a >= L / 2 || n < 1 || nt < 1)
  Error("cosine_beam_2d.geo: need L > 0, t > 0, 0 < a < L/2 (the driven piece inside the span), n >= 1 and nt >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
m = 40; // spline points per piece
xs[] = {0, L/2 - a, L/2 + a, L};
For side In {0:1}
  off = (side == 0) ? -t/2 : t/2;
  For piece In {0:2}
    pts[] = {};
    If (piece > 0)
      pts[] += last;
    EndIf
    k0 = (piece > 0) ? 1 : 0;
    For k In {k0:m}
      x = xs[piece] + (xs[piece + 1] - xs[piece]) * k / m;
      c = 1 - Cos(2 * Pi * x / L);
      y = h / 2 * c + imp * h * Sin(2 * Pi * x / L) * c / 2 + off;
      tag = 1000 * (side + 1) + 100 * piece + k;
      Point(tag) = {x, y, 0};
      pts[] += tag;
    EndFor
    last = pts[#pts[] - 1];
    first~{side}~{piece} = pts[0];
    Spline(10 * (side + 1) + piece) = pts[];
  EndFor
  end~{side} = last;
EndFor
// Cross-cuts at the piece ends, bottom to top.
For piece In {0:2}
  Line(30 + piece) = {first~{0}~{piece}, first~{1}~{piece}};
EndFor
Line(33) = {end~{0}, end~{1}};
For piece In {0:3}
  Transfinite Curve{30 + piece} = nt + 1;
EndFor
For piece In {0:2}
  cells = (piece == 1) ? 4 : n;
  Transfinite Curve{10 + piece, 20 + piece} = cells + 1;
  Curve Loop(40 + piece) = {10 + piece, 31 + piece, -(20 + piece), -(30 + piece)};
  Plane Surface(40 + piece) = {40 + piece};
  Transfinite Surface{40 + piece}; Recombine Surface{40 + piece};
EndFor
Physical Curve("left") = {30};
Physical Curve("right") = {33};
Physical Curve("apex") = {21};
Physical Curve("top") = {20, 22};
Physical Curve("bottom") = {10, 11, 12};
Physical Surface("body") = {40, 41, 42};
