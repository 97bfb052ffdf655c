// Two blocks stacked, touching along y = H but meshed separately (their nodes are not shared):
// the contact patch test. The lower block [0, W] x [0, H] has nl cells along x, the upper one
// [0, W] x [H, 2H] nu: with nl != nu the meshes do not match at the contact. ny cells through
// each block's height. With depth > 0 both are extruded along z into hexahedra, the lower block
// in nzl layers and the upper one in nzu (non-matching along z as well).
// Boundaries: base (y = 0), top (y = 2H), lower_left and upper_left (x = 0), lower_right and
// upper_right (x = W), lower_face (the lower block's top, y = H), upper_face (the upper block's
// bottom, y = H); in 3D also lower_back and upper_back (z = 0), lower_front and upper_front.
// Bodies: lower, upper.
DefineConstant[ W = {1, Name "Parameters/W", Help "width of both blocks"} ];
DefineConstant[ H = {0.5, Name "Parameters/H", Help "height of each block"} ];
DefineConstant[ nl = {5, Name "Parameters/nl", Help "cells along x, lower block"} ];
DefineConstant[ nu = {7, Name "Parameters/nu", Help "cells along x, upper block"} ];
DefineConstant[ ny = {2, Name "Parameters/ny", Help "cells through each block's height"} ];
DefineConstant[ depth = {0, Name "Parameters/depth", Help "extrusion along z (0: 2D)"} ];
DefineConstant[ nzl = {3, Name "Parameters/nzl", Help "layers along z, lower block (3D)"} ];
DefineConstant[ nzu = {4, Name "Parameters/nzu", Help "layers along z, upper block (3D)"} ];
If (W <= 0 || H <= 0 || nl < 1 || nu < 1 || ny < 1 || depth < 0 || nzl < 1 || nzu < 1)
  Error("contact_blocks.geo: need W, H > 0, nl, nu, ny, nzl, nzu >= 1 and depth >= 0");
  Abort;
EndIf
Geometry.AutoCoherence = 0; // the two blocks' coincident edges and faces must stay separate
// One block built point by point (Extrude would merge the blocks' coincident far edges).
Function MakeBlock
  // in: y0 (the block's bottom), nx, nz; out: the volume bv and its faces
  // f_base (y = y0), f_top (y = y0 + H), f_left, f_right, f_back (z = 0), f_front
  p0 = newp; Point(p0) = {0, y0, 0}; Point(p0 + 1) = {W, y0, 0}; Point(p0 + 2) = {W, y0 + H, 0};
  Point(p0 + 3) = {0, y0 + H, 0}; Point(p0 + 4) = {0, y0, depth}; Point(p0 + 5) = {W, y0, depth};
  Point(p0 + 6) = {W, y0 + H, depth}; Point(p0 + 7) = {0, y0 + H, depth};
  l0 = newl;
  Line(l0) = {p0, p0 + 1}; Line(l0 + 1) = {p0 + 3, p0 + 2}; Line(l0 + 2) = {p0 + 4, p0 + 5};
  Line(l0 + 3) = {p0 + 7, p0 + 6}; // along x
  Line(l0 + 4) = {p0, p0 + 3}; Line(l0 + 5) = {p0 + 1, p0 + 2}; Line(l0 + 6) = {p0 + 4, p0 + 7};
  Line(l0 + 7) = {p0 + 5, p0 + 6}; // along y
  Line(l0 + 8) = {p0, p0 + 4}; Line(l0 + 9) = {p0 + 1, p0 + 5}; Line(l0 + 10) = {p0 + 2, p0 + 6};
  Line(l0 + 11) = {p0 + 3, p0 + 7}; // along z
  Transfinite Curve{l0, l0 + 1, l0 + 2, l0 + 3} = nx + 1;
  Transfinite Curve{l0 + 4, l0 + 5, l0 + 6, l0 + 7} = ny + 1;
  Transfinite Curve{l0 + 8, l0 + 9, l0 + 10, l0 + 11} = nz + 1;
  c0 = newll; s0 = news;
  Curve Loop(c0) = {l0, l0 + 9, -(l0 + 2), -(l0 + 8)}; Plane Surface(s0) = {c0};              // base
  Curve Loop(c0 + 1) = {l0 + 1, l0 + 10, -(l0 + 3), -(l0 + 11)}; Plane Surface(s0 + 1) = {c0 + 1}; // top
  Curve Loop(c0 + 2) = {l0 + 4, l0 + 11, -(l0 + 6), -(l0 + 8)}; Plane Surface(s0 + 2) = {c0 + 2}; // left
  Curve Loop(c0 + 3) = {l0 + 5, l0 + 10, -(l0 + 7), -(l0 + 9)}; Plane Surface(s0 + 3) = {c0 + 3}; // right
  Curve Loop(c0 + 4) = {l0, l0 + 5, -(l0 + 1), -(l0 + 4)}; Plane Surface(s0 + 4) = {c0 + 4};     // back
  Curve Loop(c0 + 5) = {l0 + 2, l0 + 7, -(l0 + 3), -(l0 + 6)}; Plane Surface(s0 + 5) = {c0 + 5}; // front
  Transfinite Surface{s0:s0 + 5}; Recombine Surface{s0:s0 + 5};
  sl = newsl; Surface Loop(sl) = {s0:s0 + 5}; bv = newv; Volume(bv) = {sl}; Transfinite Volume{bv};
  f_base = s0; f_top = s0 + 1; f_left = s0 + 2; f_right = s0 + 3; f_back = s0 + 4; f_front = s0 + 5;
Return
If (depth == 0)
  Point(1) = {0, 0, 0}; Point(2) = {W, 0, 0}; Point(3) = {W, H, 0}; Point(4) = {0, H, 0};
  Point(5) = {0, H, 0}; Point(6) = {W, H, 0}; Point(7) = {W, 2 * H, 0}; Point(8) = {0, 2 * H, 0};
  Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
  Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
  Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
  Curve Loop(2) = {5, 6, 7, 8}; Plane Surface(2) = {2};
  Transfinite Curve{1, 3} = nl + 1; Transfinite Curve{5, 7} = nu + 1;
  Transfinite Curve{2, 4, 6, 8} = ny + 1;
  Transfinite Surface{1, 2}; Recombine Surface{1, 2};
  Physical Curve("base") = {1}; Physical Curve("lower_right") = {2};
  Physical Curve("lower_face") = {3}; Physical Curve("lower_left") = {4};
  Physical Curve("upper_face") = {5}; Physical Curve("upper_right") = {6};
  Physical Curve("top") = {7}; Physical Curve("upper_left") = {8};
  Physical Surface("lower") = {1}; Physical Surface("upper") = {2};
Else
  y0 = 0; nx = nl; nz = nzl; Call MakeBlock;
  Physical Surface("base") = {f_base}; Physical Surface("lower_face") = {f_top};
  Physical Surface("lower_left") = {f_left}; Physical Surface("lower_right") = {f_right};
  Physical Surface("lower_back") = {f_back}; Physical Surface("lower_front") = {f_front};
  Physical Volume("lower") = {bv};
  y0 = H; nx = nu; nz = nzu; Call MakeBlock;
  Physical Surface("upper_face") = {f_base}; Physical Surface("top") = {f_top};
  Physical Surface("upper_left") = {f_left}; Physical Surface("upper_right") = {f_right};
  Physical Surface("upper_back") = {f_back}; Physical Surface("upper_front") = {f_front};
  Physical Volume("upper") = {bv};
EndIf
