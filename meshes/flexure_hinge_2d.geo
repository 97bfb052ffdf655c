// A flexure hinge between two thick links, 2D. The flexure (length l, thickness t) runs along x
// from 0 to l, centred on y = 0; each link is Ll long and T thick.
// Boundaries: base (left end of the left link), drive (right end of the right link), drive_top
// (the upper face of the right link: where a travel stop meets it).
// Body: body. Cells: quadrilaterals, structured block by block.
DefineConstant[ l = {10, Name "Parameters/l", Help "flexure length"} ];
DefineConstant[ t = {1, Name "Parameters/t", Help "flexure thickness (bending depth)"} ];
DefineConstant[ Ll = {20, Name "Parameters/Ll", Help "length of each link"} ];
DefineConstant[ T = {10, Name "Parameters/T", Help "link thickness"} ];
DefineConstant[ nt = {2, Name "Parameters/nt", Help "elements through the flexure thickness"} ];
If (l <= 0 || Ll <= 0 || t <= 0 || t >= T || nt < 1)
  Error("flexure_hinge_2d.geo: need l > 0, Ll > 0, 0 < t < T and nt >= 1 (lengths and thicknesses must be positive, the flexure thinner than the links)");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
// Cells about square in the flexure; the links are meshed coarser.
nl = Ceil(nt * l / t);
nT = Ceil(nt * (T - t) / (2 * t) / 4) + 1;
nL = Ceil(nt * Ll / T) + 1;
// x stations and y stations of a 3 x 3 block grid (left link, flexure, right link)
xs[] = {-Ll, 0, l, l + Ll};
ys[] = {-T/2, -t/2, t/2, T/2};
For i In {0:3}
  For j In {0:3}
    Point(10 * i + j + 1) = {xs[i], ys[j], 0};
  EndFor
EndFor
s = 0;
For i In {0:2}
  For j In {0:2}
    // only the middle row exists in the flexure column (i = 1)
    If (i != 1 || j == 1)
      p1 = 10 * i + j + 1; p2 = 10 * (i + 1) + j + 1; p3 = p2 + 1; p4 = p1 + 1;
      s += 1;
      lines[] = {};
      Line(100 * s + 1) = {p1, p2}; Line(100 * s + 2) = {p2, p3};
      Line(100 * s + 3) = {p3, p4}; Line(100 * s + 4) = {p4, p1};
      Curve Loop(s) = {100 * s + 1, 100 * s + 2, 100 * s + 3, 100 * s + 4};
      Plane Surface(s) = {s};
      nxi = (i == 1) ? nl : nL;
      nyj = (j == 1) ? nt : nT;
      Transfinite Curve{100 * s + 1, 100 * s + 3} = nxi + 1;
      Transfinite Curve{100 * s + 2, 100 * s + 4} = nyj + 1;
      Transfinite Surface{s}; Recombine Surface{s};
      If (i == 0) base_lines[] += {100 * s + 4}; EndIf
      If (i == 2) drive_lines[] += {100 * s + 2}; EndIf
      If (i == 2 && j == 2) drive_top_lines[] += {100 * s + 3}; EndIf
    EndIf
  EndFor
EndFor
Coherence;
Physical Curve("base") = {base_lines[]};
Physical Curve("drive") = {drive_lines[]};
Physical Curve("drive_top") = {drive_top_lines[]};
Physical Surface("body") = {1:s};
