// Two pre-curved (cosine) clamped-clamped beams, one above the other, their centres tied by a
// block: the bistable switch of Qiu, Lang and Slocum (J. MEMS 13:137, 2004), in which the tie holds
// the antisymmetric (second) mode so that the beams snap through symmetrically. 2D, structured
// quadrilaterals. Each beam: span L, centre-line y = h/2 (1 - cos(2 pi x / L)) plus an antisymmetric
// imperfection imp * h * sin(2 pi x / L) (1 - cos(2 pi x / L)) / 2, thickness t measured vertically;
// the upper beam is the lower one shifted up by g. The block spans x = L/2 +- a between them.
// Boundaries: left, right (all four clamped ends), pad (the upper beam's top over the block), top,
// bottom, inner (the faces of the gap). Body: body.
DefineConstant[ L = {100, Name "Parameters/L", Help "span"} ];
DefineConstant[ h = {4, Name "Parameters/h", Help "rise of the centre lines"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "thickness of each beam (vertical)"} ];
DefineConstant[ g = {8, Name "Parameters/g", Help "vertical distance of the two centre lines"} ];
DefineConstant[ imp = {1e-3, Name "Parameters/imp", Help "antisymmetric imperfection, fraction of h"} ];
DefineConstant[ n = {50, Name "Parameters/n", Help "cells along each half of a beam"} ];
DefineConstant[ nt = {2, Name "Parameters/nt", Help "cells through a beam's thickness"} ];
DefineConstant[ a = {1, Name "Parameters/a", Help "half-width of the tying block"} ];
DefineConstant[ nb = {6, Name "Parameters/nb", Help "cells over the block's height"} ];
If (L <= 0 || t <= 0 || g <= t || a <= 0 || a >= L / 2 || n < 1 || nt < 1 || nb < 1)
  Error("cosine_double_beam_2d.geo: need L > 0, 0 < t < g (g = %g, t = %g: the beams must not overlap), 0 < a < L/2 (the block inside the span), n, nt, nb >= 1", g, t);
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
m = 40; // spline points per piece
xs[] = {0, L/2 - a, L/2 + a, L};
For beam In {0:1}
  For side In {0:1}
    off = beam * g + ((side == 0) ? -t/2 : t/2);
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
        tag = 10000 * beam + 1000 * (side + 1) + 100 * piece + k;
        Point(tag) = {x, y, 0};
        pts[] += tag;
      EndFor
      last = pts[#pts[] - 1];
      first~{beam}~{side}~{piece} = pts[0];
      Spline(100 * beam + 10 * (side + 1) + piece) = pts[];
    EndFor
    end~{beam}~{side} = last;
  EndFor
  For piece In {0:2}
    Line(100 * beam + 30 + piece) = {first~{beam}~{0}~{piece}, first~{beam}~{1}~{piece}};
  EndFor
  Line(100 * beam + 33) = {end~{beam}~{0}, end~{beam}~{1}};
  For piece In {0:3}
    Transfinite Curve{100 * beam + 30 + piece} = nt + 1;
  EndFor
  For piece In {0:2}
    cells = (piece == 1) ? 4 : n;
    Transfinite Curve{100 * beam + 10 + piece, 100 * beam + 20 + piece} = cells + 1;
    Curve Loop(100 * beam + 40 + piece) = {100 * beam + 10 + piece, 100 * beam + 31 + piece,
                                           -(100 * beam + 20 + piece), -(100 * beam + 30 + piece)};
    Plane Surface(100 * beam + 40 + piece) = {100 * beam + 40 + piece};
    Transfinite Surface{100 * beam + 40 + piece}; Recombine Surface{100 * beam + 40 + piece};
  EndFor
EndFor
// The block: from the lower beam's top (side 1) to the upper beam's bottom (side 0) over the centre piece.
Line(300) = {first~{0}~{1}~{1}, first~{1}~{0}~{1}};
Line(301) = {first~{0}~{1}~{2}, first~{1}~{0}~{2}};
Transfinite Curve{300, 301} = nb + 1;
Curve Loop(310) = {21, 301, -111, -300};
Plane Surface(310) = {310};
Transfinite Surface{310}; Recombine Surface{310};
Physical Curve("left") = {30, 130};
Physical Curve("right") = {33, 133};
Physical Curve("pad") = {121};
Physical Curve("top") = {120, 122};
Physical Curve("bottom") = {10, 11, 12};
Physical Curve("inner") = {20, 22, 110, 112};
Physical Surface("body") = {40, 41, 42, 140, 141, 142, 310};
