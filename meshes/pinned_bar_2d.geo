// A flat bar between two frictionless pins, 2D, triangles: the smallest test of the pin joints
// ("Extra constraints/Pins"). Bar from (0, 0) to (L, 0), w wide, round ends of radius w/2, an eye
// (hole) of radius rp at each end around a pin disk of the same radius.
// Bodies: bar, pins. Boundaries: eye_left, eye_right, pin_left, pin_right, outline.
Geometry.AutoCoherence = 0; // coincident pin and eye circles must stay separate curves
DefineConstant[ L = {600, Name "Parameters/L", Help "distance between the pin centres"} ];
DefineConstant[ w = {20, Name "Parameters/w", Help "bar width"} ];
DefineConstant[ rp = {4, Name "Parameters/rp", Help "pin radius = eye radius"} ];
DefineConstant[ lc = {4, Name "Parameters/lc", Help "mesh size"} ];
DefineConstant[ n_eye = {4, Name "Parameters/n_eye", Help "mesh segments per quarter circle of eyes and pins"} ];
If (rp <= 0 || rp >= w / 2 || L <= 2 * rp || lc <= 0 || n_eye < 1)
  Error("pinned_bar_2d.geo: need 0 < rp < w/2 (the eyes inside the round ends), L > 2 rp, lc > 0 and n_eye >= 1");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
R = w / 2;

// Four quarter arcs from +x, the same for the eye and the pin at one centre.
Macro "EyeCircle"
  c_ = newp; Point(c_) = {cx_, 0, 0, lc};
  For k_ In {0:3}
    q_[k_] = newp; Point(q_[k_]) = {cx_ + rp * Cos(k_ * Pi / 2), rp * Sin(k_ * Pi / 2), 0, lc};
  EndFor
  For k_ In {0:3}
    circle_[k_] = newc; Circle(circle_[k_]) = {q_[k_], c_, q_[(k_ + 1) % 4]};
  EndFor
  Transfinite Curve{circle_[]} = n_eye + 1;
  loop_ = newll; Curve Loop(loop_) = {circle_[]};
Return

cl = newp; Point(cl) = {0, 0, 0, lc}; cr = newp; Point(cr) = {L, 0, 0, lc};
p1 = newp; Point(p1) = {0, R, 0, lc}; p2 = newp; Point(p2) = {L, R, 0, lc};
p3 = newp; Point(p3) = {L + R, 0, 0, lc}; p4 = newp; Point(p4) = {L, -R, 0, lc};
p5 = newp; Point(p5) = {0, -R, 0, lc}; p6 = newp; Point(p6) = {-R, 0, 0, lc};
o[0] = newc; Line(o[0]) = {p1, p2};
o[1] = newc; Circle(o[1]) = {p2, cr, p3};
o[2] = newc; Circle(o[2]) = {p3, cr, p4};
o[3] = newc; Line(o[3]) = {p4, p5};
o[4] = newc; Circle(o[4]) = {p5, cl, p6};
o[5] = newc; Circle(o[5]) = {p6, cl, p1};
outer = newll; Curve Loop(outer) = {o[]};
cx_ = 0;
Call "EyeCircle";
eye_left[] = circle_[]; hole_left = loop_;
cx_ = L;
Call "EyeCircle";
eye_right[] = circle_[]; hole_right = loop_;
bar = news; Plane Surface(bar) = {outer, hole_left, hole_right};
cx_ = 0;
Call "EyeCircle";
pin_left[] = circle_[]; pl = news; Plane Surface(pl) = {loop_};
cx_ = L;
Call "EyeCircle";
pin_right[] = circle_[]; pr = news; Plane Surface(pr) = {loop_};
Mesh.CharacteristicLengthMax = lc;

Physical Surface("bar") = {bar};
Physical Surface("pins") = {pl, pr};
Physical Curve("eye_left") = {eye_left[]};
Physical Curve("eye_right") = {eye_right[]};
Physical Curve("pin_left") = {pin_left[]};
Physical Curve("pin_right") = {pin_right[]};
Physical Curve("outline") = {o[]};
