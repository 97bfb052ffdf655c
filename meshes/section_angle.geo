// L (angle) cross-section for section_torsion: horizontal leg b1 x t along x, vertical leg t x b2
// along y, outer corner at the origin, inner corner rounded with radius r (0: sharp, where the
// torsional shear stress is infinite). Thin-walled theory puts the shear centre at the crossing
// of the leg midlines, (t/2, t/2), with Gamma ~ t^3 (b1'^3 + b2'^3) / 36, b' = b - t/2.
// Cells: unstructured triangles (quads = 0) or quadrilaterals (quads = 1), size t / n.
// Boundary: boundary. Body: section.
DefineConstant[ b1 = {40, Name "Parameters/b1", Help "length of the leg along x"} ];
DefineConstant[ b2 = {30, Name "Parameters/b2", Help "length of the leg along y"} ];
DefineConstant[ t = {4, Name "Parameters/t", Help "leg thickness"} ];
DefineConstant[ r = {2, Name "Parameters/r", Help "fillet radius of the inner corner (0: sharp)"} ];
DefineConstant[ n = {4, Name "Parameters/n", Help "elements through the thickness"} ];
DefineConstant[ quads = {0, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (t <= 0 || t >= b1 || t >= b2 || r < 0 || r >= b1 - t || r >= b2 - t || n < 1)
  Error("section_angle.geo: need 0 < t < b1, t < b2 (the legs longer than thick), 0 <= r < b1 - t, r < b2 - t (the fillet on the inner edges) and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
lc = t / n;
X[] = {0, b1, b1, t, t, 0};
Y[] = {0, 0, t, t, b2, b2};
F[] = {0, 0, 0, 1, 0, 0};
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
