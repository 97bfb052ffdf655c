// The flexure hinge of flexure_hinge_2d.geo with its travel stop drawn in the geometry: a steel
// pin (a ring of outer radius rp and inner radius rp/2, centred at (xp, yp)) above the right
// link, meshed with the hinge as a second body. Held by its bore (pin_bore), it stops the link
// through Contact/Pairs, where flexure_hinge_stop.prm has a rigid circle (Contact/Obstacles).
// Boundaries: those of flexure_hinge_2d.geo, and pin_arc (the pin's outer circle), pin_bore.
// Bodies: body (the hinge), pin.
Include "flexure_hinge_2d.geo";
DefineConstant[ xp = {25, Name "Parameters/xp", Help "pin centre, x"} ];
DefineConstant[ yp = {10.634, Name "Parameters/yp", Help "pin centre, y"} ];
DefineConstant[ rp = {2, Name "Parameters/rp", Help "pin radius"} ];
DefineConstant[ np = {24, Name "Parameters/np", Help "cells around the pin"} ];
If (rp <= 0 || yp - rp <= T / 2 || np < 8)
  Error("flexure_hinge_pin_2d.geo: need rp > 0, the pin clear of the link (yp - rp > T/2) and np >= 8");
  Abort;
EndIf
c = newp; Point(c) = {xp, yp, 0};
For k In {0:3}
  Point(c + 1 + k) = {xp + rp * Cos(k * Pi / 2), yp + rp * Sin(k * Pi / 2), 0};
  Point(c + 5 + k) = {xp + rp / 2 * Cos(k * Pi / 2), yp + rp / 2 * Sin(k * Pi / 2), 0};
EndFor
a = newl;
For k In {0:3}
  Circle(a + k) = {c + 1 + k, c, c + 1 + (k + 1) % 4};
  Circle(a + 4 + k) = {c + 5 + k, c, c + 5 + (k + 1) % 4};
  Line(a + 8 + k) = {c + 5 + k, c + 1 + k};
EndFor
ps = news;
For k In {0:3}
  Curve Loop(ps + k) = {a + 8 + k, a + k, -(a + 8 + (k + 1) % 4), -(a + 4 + k)};
  Plane Surface(ps + k) = {ps + k};
EndFor
Transfinite Curve{a:a + 7} = np / 4 + 1; Transfinite Curve{a + 8:a + 11} = 3;
Transfinite Surface{ps:ps + 3}; Recombine Surface{ps:ps + 3};
Physical Curve("pin_arc") = {a:a + 3};
Physical Curve("pin_bore") = {a + 4:a + 7};
Physical Surface("pin") = {ps:ps + 3};
