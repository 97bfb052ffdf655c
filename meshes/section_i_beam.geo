// I (H) cross-section for section_torsion, doubly symmetric about the origin: overall height h,
// flanges bf x tf, web thickness tw, web-flange corners rounded with radius r (rolled sections;
// 0: sharp). Thin-walled theory: Gamma = tf bf^3 h'^2 / 24, h' = h - tf (Timoshenko and Gere,
// Theory of Elastic Stability, sec. 5.3), J ~ (2 bf tf^3 + h' tw^3) / 3.
// Cells: unstructured triangles (quads = 0) or quadrilaterals (quads = 1), size min(tw, tf) / n.
// Boundary: boundary. Body: section.
DefineConstant[ h = {200, Name "Parameters/h", Help "overall height"} ];
DefineConstant[ bf = {100, Name "Parameters/bf", Help "flange width"} ];
DefineConstant[ tf = {8.5, Name "Parameters/tf", Help "flange thickness"} ];
DefineConstant[ tw = {5.6, Name "Parameters/tw", Help "web thickness"} ];
DefineConstant[ r = {12, Name "Parameters/r", Help "fillet radius of the web-flange corners (0: sharp)"} ];
DefineConstant[ n = {3, Name "Parameters/n", Help "elements through the thinner wall"} ];
DefineConstant[ quads = {0, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (tw <= 0 || tw >= bf || tf <= 0 || 2 * tf >= h || r < 0 || 2 * r >= bf - tw || 2 * r >= h - 2 * tf || n < 1)
  Error("section_i_beam.geo: need 0 < tw < bf, 0 < tf < h/2, 0 <= r < (bf - tw)/2, 2 r < h - 2 tf (the fillets on the inner edges) and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
lc = (tf < tw ? tf : tw) / n;
X[] = {-bf/2, bf/2, bf/2, tw/2, tw/2, bf/2, bf/2, -bf/2, -bf/2, -tw/2, -tw/2, -bf/2};
Y[] = {-h/2, -h/2, -h/2 + tf, -h/2 + tf, h/2 - tf, h/2 - tf, h/2, h/2, h/2 - tf, h/2 - tf, -h/2 + tf, -h/2 + tf};
F[] = {0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0};
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
