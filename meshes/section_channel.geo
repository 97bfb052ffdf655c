// Channel (C) cross-section for section_torsion: web of thickness tw along y at x = 0..tw, two
// flanges bf x tf towards +x, overall height h, web-flange corners rounded with radius r. Thin-
// walled theory (Timoshenko and Gere, Mechanics of Materials, sec. 6.9) puts the shear centre on
// the axis of symmetry at e = 3 b^2 tf / (6 b tf + h' tw) outside the web midline, b = bf - tw/2,
// h' = h - tf. Cells: unstructured triangles (quads = 0) or quadrilaterals (quads = 1), size
// min(tw, tf) / n. Boundary: boundary. Body: section.
DefineConstant[ h = {100, Name "Parameters/h", Help "overall height"} ];
DefineConstant[ bf = {50, Name "Parameters/bf", Help "flange width (overall)"} ];
DefineConstant[ tf = {4, Name "Parameters/tf", Help "flange thickness"} ];
DefineConstant[ tw = {4, Name "Parameters/tw", Help "web thickness"} ];
DefineConstant[ r = {0, Name "Parameters/r", Help "fillet radius of the web-flange corners (0: sharp)"} ];
DefineConstant[ n = {3, Name "Parameters/n", Help "elements through the thinner wall"} ];
DefineConstant[ quads = {0, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (tw <= 0 || tw >= bf || tf <= 0 || 2 * tf >= h || r < 0 || r >= bf - tw || 2 * r >= h - 2 * tf || n < 1)
  Error("section_channel.geo: need 0 < tw < bf, 0 < tf < h/2, 0 <= r < bf - tw, 2 r < h - 2 tf (the fillets on the inner edges) and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
lc = (tf < tw ? tf : tw) / n;
X[] = {0, bf, bf, tw, tw, bf, bf, 0};
Y[] = {0, 0, tf, tf, h - tf, h - tf, h, h};
F[] = {0, 0, 0, 1, 1, 0, 0, 0};
// Outline X[], Y[] (counterclockwise); corners with F[] = 1 are rounded with radius r: the arc is
// tangent to both edges, its centre at C - r u + r w (u: unit direction arriving at C, w: leaving).
N = #X[];
For i In {0:N-1}
  ip = (i + N - 1) % N; inext = (i + 1) % N;
  ux = X[i] - X[ip]; uy = Y[i] - Y[ip]; lu = Sqrt(ux^2 + uy^2); ux = ux / lu; uy = uy / lu;
  wx = X[inext] - X[i]; wy = Y[inext] - Y[i]; lw = Sqrt(wx^2 + wy^2); wx = wx / lw; wy = wy / lw;
  If (F[i] && r > 0)
    // at least 8 facets per quarter circle: a concave kink of at most 11.25 degrees per vertex
    lc_arc = (lc < Pi * r / 16 ? lc : Pi * r / 16);
    pa[i] = newp; Point(pa[i]) = {X[i] - r * ux, Y[i] - r * uy, 0, lc_arc};
    pc = newp; Point(pc) = {X[i] - r * ux + r * wx, Y[i] - r * uy + r * wy, 0, lc_arc};
    pb[i] = newp; Point(pb[i]) = {X[i] + r * wx, Y[i] + r * wy, 0, lc_arc};
    arc[i] = newl; Circle(arc[i]) = {pa[i], pc, pb[i]};
  Else
    pa[i] = newp; Point(pa[i]) = {X[i], Y[i], 0, lc};
    pb[i] = pa[i]; arc[i] = 0;
  EndIf
EndFor
edges[] = {};
For i In {0:N-1}
  If (arc[i] != 0)
    edges[] += {arc[i]};
  EndIf
  e = newl; Line(e) = {pb[i], pa[(i + 1) % N]}; edges[] += {e};
EndFor
Curve Loop(1) = edges[]; Plane Surface(1) = {1};
If (quads)
  // Blossom full-quad recombination: all cells quadrilateral, about lc / 2 (each is split in
  // four); the Frontal-Delaunay-for-quads algorithm (8) crashes gmsh 4.8.4 here.
  Mesh.RecombinationAlgorithm = 3; Recombine Surface{1};
EndIf
Physical Curve("boundary") = {edges[]};
Physical Surface("section") = {1};
