// Equilateral triangle of side a for section_torsion, centroid at the origin, one side vertical at
// x = -h/3 (h = a sqrt(3)/2), the opposite vertex at (2h/3, 0). Saint-Venant's exact solution
// (Timoshenko and Goodier, Theory of Elasticity, sec. 107): omega = (y^3 - 3 x^2 y) / (2 h), a cubic,
// J = sqrt(3) a^4 / 80, tau_max = 20 T / a^3 at the middle of each side; integrating omega^2
// gives Gamma = sqrt(3) a^6 / 40320. Cells: unstructured triangles (quads = 0) or quadrilaterals
// (quads = 1), size a / n. Boundary: boundary. Body: section.
DefineConstant[ a = {10, Name "Parameters/a", Help "side"} ];
DefineConstant[ n = {8, Name "Parameters/n", Help "elements along a side"} ];
DefineConstant[ quads = {0, Name "Parameters/quads", Help "1: quadrilaterals, 0: triangles"} ];
If (a <= 0 || n < 1)
  Error("section_triangle.geo: need a > 0 and n >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
lc = a / n;
r = 0;
h = a * Sqrt(3) / 2;
X[] = {-h/3, 2*h/3, -h/3};
Y[] = {-a/2, 0, a/2};
F[] = {0, 0, 0};
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
