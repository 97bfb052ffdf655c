// Jansen (Strandbeest) leg of the seed paper (Kartal and Kavlak; digest section D) as a pin-jointed
// plane structure at crank angle theta2, triangles. Frame and joint names as in
// solver/mechanisms/jansen/README.md: E at the origin, x horizontal, y up, theta2 = direction of
// A->B counter-clockwise. The pose is assembled here from the link lengths with the same circle
// intersections and branches as the kinematics library (C right of B->E, G left of B->E, D left
// of E->C, F right of D->G, H left of G->F).
//
// Design (the paper gives none): every link is a flat bar w wide (in the plane) and as thick as
// Material/Thickness, with round ends of radius w/2 around its joints; the ternary links CDE and
// FGH are triangles of such bars (a plate with a triangular window, fillets of radius rho). Each
// joint is a pin disk of radius rp, and each link an eye (hole) of the same radius around it;
// "Extra constraints/Pins" ties them (radial contact, no moment). The crank's eye at A is the
// motor shaft (clamp it), pin_E is the ground pivot (clamp it), the foot is a hole of radius rp at
// H (the foot pad's bolt), where the load goes.
//
// Bodies: crank, link_BC, link_BG, link_CDE, link_EG, link_DF, link_FGH, pins.
// Boundaries: eye_<link>_<joint> (eye_AB_A, eye_AB_B, eye_BC_B, ...), pin_<joint> (B C D E F G),
// foot, outline (every other edge). With solid = 1 the same names are volumes and the surfaces
// swept by those curves (a 3D solid t thick; all links in the same layer, z in [0, t]).
// (gmsh parses the rest of a line before a macro it calls: every Call stands on its own line)

DefineConstant[ theta2 = {37.2089, Name "Parameters/theta2", Help "crank angle, degrees (37.2089: foot lowest; 302.8: the paper's touchdown pose)"} ];
DefineConstant[ w = {30, Name "Parameters/w", Help "bar width in the plane of the leg, mm"} ];
DefineConstant[ rp = {5, Name "Parameters/rp", Help "pin radius = eye hole radius, mm"} ];
DefineConstant[ rho = {5, Name "Parameters/rho", Help "fillet radius of the ternary links' windows, mm"} ];
DefineConstant[ lc = {5, Name "Parameters/lc", Help "mesh size along the bars, mm"} ];
DefineConstant[ n_eye = {4, Name "Parameters/n_eye", Help "mesh segments per quarter of each eye and pin circle"} ];
DefineConstant[ quads = {0, Name "Parameters/quads", Help "plane model: 0 triangles, 1 quadrilaterals (finite strain, contact)"} ];
DefineConstant[ solid = {0, Name "Parameters/solid", Help "0: plane model (triangles); 1: 3D solid of thickness t (hexahedra, two through t)"} ];
DefineConstant[ t = {10, Name "Parameters/t", Help "thickness of the links of the 3D solid, mm (the plane model takes Material/Thickness)"} ];
DefineConstant[ EA = {193.96, Name "Parameters/EA", Help "ground link r1, mm"} ];
DefineConstant[ theta1 = {11.6, Name "Parameters/theta1", Help "direction of E->A, degrees"} ];
DefineConstant[ AB = {75, Name "Parameters/AB", Help "crank r2, mm"} ];
DefineConstant[ BC = {250, Name "Parameters/BC", Help "r3, mm"} ];
DefineConstant[ BG = {309.5, Name "Parameters/BG", Help "r4, mm"} ];
DefineConstant[ CE = {207.5, Name "Parameters/CE", Help "r5, mm"} ];
DefineConstant[ DE = {200.5, Name "Parameters/DE", Help "r5', mm"} ];
DefineConstant[ CD = {279, Name "Parameters/CD", Help "r5'', mm"} ];
DefineConstant[ EG = {196.5, Name "Parameters/EG", Help "r6, mm"} ];
DefineConstant[ DF = {197, Name "Parameters/DF", Help "r7, mm"} ];
DefineConstant[ FG = {183, Name "Parameters/FG", Help "r8, mm"} ];
DefineConstant[ GH = {245, Name "Parameters/GH", Help "r8', mm"} ];
DefineConstant[ FH = {328, Name "Parameters/FH", Help "r8'', mm"} ];
If (w <= 0 || rp <= 0 || rp >= w / 2 || rho <= 0 || lc <= 0 || n_eye < 1 || t <= 0 ||
    EA <= 0 || AB <= 0 || BC <= 0 || BG <= 0 || CE <= 0 || DE <= 0 || CD <= 0 || EG <= 0 || DF <= 0 || FG <= 0 || GH <= 0 || FH <= 0)
  Error("jansen_leg.geo: need 0 < rp < w/2 (the eyes inside the bars' round ends), rho > 0, lc > 0, n_eye >= 1, t > 0 and every link length (EA, AB, BC, BG, CE, DE, CD, EG, DF, FG, GH, FH) > 0");
  Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
EndIf
If (quads != 0 && quads != 1)
  Error("jansen_leg.geo: need quads = 0 (triangles) or 1 (quadrilaterals), got %g", quads);
  Abort;
EndIf
R = w / 2;
// Coincident pin and eye circles must stay separate curves. The plane model switches gmsh's
// merging of duplicate entities off; the extrusion of the solid needs it on, so there every body
// sits dz higher than the previous one instead (1e-5 mm; the pin ties match nodes to 1e-3 rp).
Geometry.AutoCoherence = (solid == 0) ? 0 : 1;
dz = (solid == 0) ? 0 : 1e-5;
z_ = 0;

// ---------------------------------------------------------------- pose (mm)
// Intersection of the circles (P1, r1) and (P2, r2) on the left (side = 1) or right (side = -1)
// of P1 -> P2.
Macro "CircleIntersection"
  dx_ = x2_ - x1_; dy_ = y2_ - y1_; d_ = Sqrt(dx_^2 + dy_^2);
  a_ = (r1_^2 - r2_^2 + d_^2) / (2 * d_); h_ = Sqrt(r1_^2 - a_^2);
  If (r1_^2 - a_^2 < 0)
    Error("jansen_leg.geo: the links cannot be assembled at theta2 = %g deg: need |r1 - r2| <= d <= r1 + r2 for the two links (r1, r2: BC, CE; BG, EG; DE, CD; DF, FG; GH, FH) that meet at a joint d away from their other ends", theta2);
    Abort; // gmsh reads on after an Error: stop, or a later error replaces this message
  EndIf
  xo_ = x1_ + (a_ * dx_ - side_ * h_ * dy_) / d_;
  yo_ = y1_ + (a_ * dy_ + side_ * h_ * dx_) / d_;
Return

xE = 0; yE = 0;
xA = EA * Cos(theta1 * Pi / 180); yA = EA * Sin(theta1 * Pi / 180);
xB = xA + AB * Cos(theta2 * Pi / 180); yB = yA + AB * Sin(theta2 * Pi / 180);
x1_ = xB; y1_ = yB; x2_ = xE; y2_ = yE; r1_ = BC; r2_ = CE; side_ = -1; Call "CircleIntersection";
xC = xo_; yC = yo_;
x1_ = xB; y1_ = yB; x2_ = xE; y2_ = yE; r1_ = BG; r2_ = EG; side_ = 1; Call "CircleIntersection";
xG = xo_; yG = yo_;
x1_ = xE; y1_ = yE; x2_ = xC; y2_ = yC; r1_ = DE; r2_ = CD; side_ = 1; Call "CircleIntersection";
xD = xo_; yD = yo_;
x1_ = xD; y1_ = yD; x2_ = xG; y2_ = yG; r1_ = DF; r2_ = FG; side_ = -1; Call "CircleIntersection";
xF = xo_; yF = yo_;
x1_ = xG; y1_ = yG; x2_ = xF; y2_ = yF; r1_ = GH; r2_ = FH; side_ = 1; Call "CircleIntersection";
xH = xo_; yH = yo_;
Printf("Jansen leg at theta2 = %g deg: H = (%.4f, %.4f) mm", theta2, xH, yH);

// ---------------------------------------------------------------- building blocks
// Circle of radius rp around (cx_, cy_) as four quarter arcs starting on +x, so that every eye and
// pin at one joint has the same nodes. Returns circle_[] (curves) and loop_.
Macro "EyeCircle"
  c_ = newp; Point(c_) = {cx_, cy_, z_, lc};
  For k_ In {0:3}
    q_[k_] = newp; Point(q_[k_]) = {cx_ + rp * Cos(k_ * Pi / 2), cy_ + rp * Sin(k_ * Pi / 2), z_, lc};
  EndFor
  For k_ In {0:3}
    circle_[k_] = newc; Circle(circle_[k_]) = {q_[k_], c_, q_[(k_ + 1) % 4]};
  EndFor
  Transfinite Curve{circle_[]} = n_eye + 1;
  loop_ = newll; Curve Loop(loop_) = {circle_[]};
Return

// Pin disk at (cx_, cy_): returns pin_surface_ and pin_curves_[].
Macro "PinDisk"
  z_ += dz;
  Call "EyeCircle";
  pin_surface_ = news; Plane Surface(pin_surface_) = {loop_};
  pin_curves_[] = circle_[];
Return

// Binary link between (xp_, yp_) and (xq_, yq_) with eyes at both ends: returns link_surface_,
// eye_p_[], eye_q_[], outline_[].
Macro "BarLink"
  z_ += dz;
  L_ = Sqrt((xq_ - xp_)^2 + (yq_ - yp_)^2); ux_ = (xq_ - xp_) / L_; uy_ = (yq_ - yp_) / L_;
  nx_ = -uy_; ny_ = ux_;
  cp_ = newp; Point(cp_) = {xp_, yp_, z_, lc};
  cq_ = newp; Point(cq_) = {xq_, yq_, z_, lc};
  p1_ = newp; Point(p1_) = {xp_ + R * nx_, yp_ + R * ny_, z_, lc};
  p2_ = newp; Point(p2_) = {xq_ + R * nx_, yq_ + R * ny_, z_, lc};
  p3_ = newp; Point(p3_) = {xq_ + R * ux_, yq_ + R * uy_, z_, lc};
  p4_ = newp; Point(p4_) = {xq_ - R * nx_, yq_ - R * ny_, z_, lc};
  p5_ = newp; Point(p5_) = {xp_ - R * nx_, yp_ - R * ny_, z_, lc};
  p6_ = newp; Point(p6_) = {xp_ - R * ux_, yp_ - R * uy_, z_, lc};
  o_[0] = newc; Line(o_[0]) = {p1_, p2_};
  o_[1] = newc; Circle(o_[1]) = {p2_, cq_, p3_};
  o_[2] = newc; Circle(o_[2]) = {p3_, cq_, p4_};
  o_[3] = newc; Line(o_[3]) = {p4_, p5_};
  o_[4] = newc; Circle(o_[4]) = {p5_, cp_, p6_};
  o_[5] = newc; Circle(o_[5]) = {p6_, cp_, p1_};
  outer_ = newll; Curve Loop(outer_) = {o_[]};
  cx_ = xp_; cy_ = yp_; Call "EyeCircle";
  eye_p_[] = circle_[]; hole_p_ = loop_;
  cx_ = xq_; cy_ = yq_; Call "EyeCircle";
  eye_q_[] = circle_[]; hole_q_ = loop_;
  link_surface_ = news; Plane Surface(link_surface_) = {outer_, hole_p_, hole_q_};
  outline_[] = o_[];
Return

// Ternary link: a triangle of bars around the joints (x0_, y0_), (x1t_, y1t_), (x2t_, y2t_),
// counter-clockwise; eyes at the first two or all three corners (holes_ = 2 or 3). Returns
// link_surface_, eye_t0_[], eye_t1_[], eye_t2_[], outline_[].
Macro "TernaryLink"
  z_ += dz;
  tx_[0] = x0_; ty_[0] = y0_; tx_[1] = x1t_; ty_[1] = y1t_; tx_[2] = x2t_; ty_[2] = y2t_;
  For i_ In {0:2}
    j_ = (i_ + 1) % 3;
    el_ = Sqrt((tx_[j_] - tx_[i_])^2 + (ty_[j_] - ty_[i_])^2);
    ex_[i_] = (tx_[j_] - tx_[i_]) / el_; ey_[i_] = (ty_[j_] - ty_[i_]) / el_; // edge i -> i+1
    // outward normal of a counter-clockwise edge
    onx_[i_] = ey_[i_]; ony_[i_] = -ex_[i_];
  EndFor
  For i_ In {0:2}
    tc_[i_] = newp; Point(tc_[i_]) = {tx_[i_], ty_[i_], z_, lc};
    k_ = (i_ + 2) % 3; // incoming edge
    tin_[i_] = newp; Point(tin_[i_]) = {tx_[i_] + R * onx_[k_], ty_[i_] + R * ony_[k_], z_, lc};
    tout_[i_] = newp; Point(tout_[i_]) = {tx_[i_] + R * onx_[i_], ty_[i_] + R * ony_[i_], z_, lc};
  EndFor
  For i_ In {0:2}
    corner_[i_] = newc; Circle(corner_[i_]) = {tin_[i_], tc_[i_], tout_[i_]};
    side_line_[i_] = newc; Line(side_line_[i_]) = {tout_[i_], tin_[(i_ + 1) % 3]};
    o_[2 * i_] = corner_[i_]; o_[2 * i_ + 1] = side_line_[i_];
  EndFor
  outer_ = newll; Curve Loop(outer_) = {o_[]};
  // Window: the inner edges of the bars (offset R inwards), corners filleted with radius rho.
  For i_ In {0:2}
    k_ = (i_ + 2) % 3;
    // interior angle at corner i between edge i (out) and edge k reversed (in)
    ca_ = -(ex_[i_] * ex_[k_] + ey_[i_] * ey_[k_]); alpha_ = Acos(ca_);
    bx_ = ex_[i_] - ex_[k_]; by_ = ey_[i_] - ey_[k_]; bl_ = Sqrt(bx_^2 + by_^2); bx_ /= bl_; by_ /= bl_;
    s_ = (R + rho) / Sin(alpha_ / 2);
    fc_[i_] = newp; Point(fc_[i_]) = {tx_[i_] + s_ * bx_, ty_[i_] + s_ * by_, z_, lc};
    fin_[i_] = newp; Point(fin_[i_]) = {tx_[i_] + s_ * bx_ + rho * onx_[k_], ty_[i_] + s_ * by_ + rho * ony_[k_], z_, lc};
    fout_[i_] = newp; Point(fout_[i_]) = {tx_[i_] + s_ * bx_ + rho * onx_[i_], ty_[i_] + s_ * by_ + rho * ony_[i_], z_, lc};
  EndFor
  For i_ In {0:2}
    w_[2 * i_] = newc; Circle(w_[2 * i_]) = {fin_[i_], fc_[i_], fout_[i_]};
    w_[2 * i_ + 1] = newc; Line(w_[2 * i_ + 1]) = {fout_[i_], fin_[(i_ + 1) % 3]};
  EndFor
  window_ = newll; Curve Loop(window_) = {w_[]};
  cx_ = tx_[0]; cy_ = ty_[0]; Call "EyeCircle";
  eye_t0_[] = circle_[]; h0_ = loop_;
  cx_ = tx_[1]; cy_ = ty_[1]; Call "EyeCircle";
  eye_t1_[] = circle_[]; h1_ = loop_;
  If (holes_ == 3)
    cx_ = tx_[2]; cy_ = ty_[2]; Call "EyeCircle";
    eye_t2_[] = circle_[]; h2_ = loop_;
    link_surface_ = news; Plane Surface(link_surface_) = {outer_, window_, h0_, h1_, h2_};
  Else
    link_surface_ = news; Plane Surface(link_surface_) = {outer_, window_, h0_, h1_};
  EndIf
  outline_[] = {o_[], w_[]};
Return

// ---------------------------------------------------------------- the leg
outline[] = {};
xp_ = xA; yp_ = yA; xq_ = xB; yq_ = yB; Call "BarLink";
crank = link_surface_; eye_AB_A[] = eye_p_[]; eye_AB_B[] = eye_q_[]; outline[] += outline_[];
xp_ = xB; yp_ = yB; xq_ = xC; yq_ = yC; Call "BarLink";
link_BC = link_surface_; eye_BC_B[] = eye_p_[]; eye_BC_C[] = eye_q_[]; outline[] += outline_[];
xp_ = xB; yp_ = yB; xq_ = xG; yq_ = yG; Call "BarLink";
link_BG = link_surface_; eye_BG_B[] = eye_p_[]; eye_BG_G[] = eye_q_[]; outline[] += outline_[];
xp_ = xE; yp_ = yE; xq_ = xG; yq_ = yG; Call "BarLink";
link_EG = link_surface_; eye_EG_E[] = eye_p_[]; eye_EG_G[] = eye_q_[]; outline[] += outline_[];
xp_ = xD; yp_ = yD; xq_ = xF; yq_ = yF; Call "BarLink";
link_DF = link_surface_; eye_DF_D[] = eye_p_[]; eye_DF_F[] = eye_q_[]; outline[] += outline_[];

// CDE: counter-clockwise order decided by the sign of the area.
If ((xD - xC) * (yE - yC) - (yD - yC) * (xE - xC) > 0)
  x0_ = xC; y0_ = yC; x1t_ = xD; y1t_ = yD; x2t_ = xE; y2t_ = yE; holes_ = 3; Call "TernaryLink";
  eye_CDE_C[] = eye_t0_[]; eye_CDE_D[] = eye_t1_[]; eye_CDE_E[] = eye_t2_[];
Else
  x0_ = xD; y0_ = yD; x1t_ = xC; y1t_ = yC; x2t_ = xE; y2t_ = yE; holes_ = 3; Call "TernaryLink";
  eye_CDE_D[] = eye_t0_[]; eye_CDE_C[] = eye_t1_[]; eye_CDE_E[] = eye_t2_[];
EndIf
link_CDE = link_surface_; outline[] += outline_[];
// FGH: H is the third corner. Its hole holds the foot pad's bolt; the foot load is spread over
// that circle, so its resultant acts exactly at H with no moment about H.
If ((xG - xF) * (yH - yF) - (yG - yF) * (xH - xF) > 0)
  x0_ = xF; y0_ = yF; x1t_ = xG; y1t_ = yG; x2t_ = xH; y2t_ = yH; holes_ = 3;
  Call "TernaryLink";
  eye_FGH_F[] = eye_t0_[]; eye_FGH_G[] = eye_t1_[];
Else
  x0_ = xG; y0_ = yG; x1t_ = xF; y1t_ = yF; x2t_ = xH; y2t_ = yH; holes_ = 3;
  Call "TernaryLink";
  eye_FGH_G[] = eye_t0_[]; eye_FGH_F[] = eye_t1_[];
EndIf
link_FGH = link_surface_; foot[] = eye_t2_[]; outline[] += outline_[];

pins[] = {};
cx_ = xB; cy_ = yB; Call "PinDisk";
pins[] += pin_surface_; pin_B[] = pin_curves_[];
cx_ = xC; cy_ = yC; Call "PinDisk";
pins[] += pin_surface_; pin_C[] = pin_curves_[];
cx_ = xD; cy_ = yD; Call "PinDisk";
pins[] += pin_surface_; pin_D[] = pin_curves_[];
cx_ = xE; cy_ = yE; Call "PinDisk";
pins[] += pin_surface_; pin_E[] = pin_curves_[];
cx_ = xF; cy_ = yF; Call "PinDisk";
pins[] += pin_surface_; pin_F[] = pin_curves_[];
cx_ = xG; cy_ = yG; Call "PinDisk";
pins[] += pin_surface_; pin_G[] = pin_curves_[];

Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthFromPoints = 1;

If (solid == 0)
// quads = 1: quadrilaterals (Blossom recombination, as the 3D solid's faces), for the analyses
// that need them (finite strain, contact).
If (quads == 1)
  Mesh.RecombineAll = 1;
  Mesh.RecombinationAlgorithm = 1; // Blossom
EndIf
Physical Surface("crank") = {crank};
Physical Surface("link_BC") = {link_BC};
Physical Surface("link_BG") = {link_BG};
Physical Surface("link_CDE") = {link_CDE};
Physical Surface("link_EG") = {link_EG};
Physical Surface("link_DF") = {link_DF};
Physical Surface("link_FGH") = {link_FGH};
Physical Surface("pins") = {pins[]};
Physical Curve("eye_AB_A") = {eye_AB_A[]};
Physical Curve("eye_AB_B") = {eye_AB_B[]};
Physical Curve("eye_BC_B") = {eye_BC_B[]};
Physical Curve("eye_BC_C") = {eye_BC_C[]};
Physical Curve("eye_BG_B") = {eye_BG_B[]};
Physical Curve("eye_BG_G") = {eye_BG_G[]};
Physical Curve("eye_CDE_C") = {eye_CDE_C[]};
Physical Curve("eye_CDE_D") = {eye_CDE_D[]};
Physical Curve("eye_CDE_E") = {eye_CDE_E[]};
Physical Curve("eye_EG_E") = {eye_EG_E[]};
Physical Curve("eye_EG_G") = {eye_EG_G[]};
Physical Curve("eye_DF_D") = {eye_DF_D[]};
Physical Curve("eye_DF_F") = {eye_DF_F[]};
Physical Curve("eye_FGH_F") = {eye_FGH_F[]};
Physical Curve("eye_FGH_G") = {eye_FGH_G[]};
Physical Curve("pin_B") = {pin_B[]};
Physical Curve("pin_C") = {pin_C[]};
Physical Curve("pin_D") = {pin_D[]};
Physical Curve("pin_E") = {pin_E[]};
Physical Curve("pin_F") = {pin_F[]};
Physical Curve("pin_G") = {pin_G[]};
Physical Curve("foot") = {foot[]};
Physical Curve("outline") = {outline[]};
Else
// ---------------------------------------------------------------- 3D solid
// The surfaces are meshed with quadrilaterals only (full-quad recombination, which splits every
// curve segment in two: the same on coincident pin and eye circles, so their nodes still match),
// then extruded by t in one layer of hexahedra (Q2 through t: bending stress linear in z exactly). Boundaries are the faces swept by the named curves.
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1; // Blossom
lat_curve[] = {}; lat_surface[] = {};
Macro "Solid"
  bnd_[] = Abs(Boundary{ Surface{s_}; });
  ex_[] = Extrude {0, 0, t} { Surface{s_}; Layers{1}; Recombine; };
  vol_ = ex_[1];
  For k_ In {0:#bnd_[] - 1}
    lat_curve[] += bnd_[k_]; lat_surface[] += ex_[2 + k_];
  EndFor
Return
// Lateral faces swept by the curves in curves_[]: faces_[].
Macro "Swept"
  faces_[] = {};
  For k_ In {0:#curves_[] - 1}
    For m_ In {0:#lat_curve[] - 1}
      If (lat_curve[m_] == curves_[k_])
        faces_[] += lat_surface[m_];
      EndIf
    EndFor
  EndFor
Return
s_ = crank;
Call "Solid";
Physical Volume("crank") = {vol_};
s_ = link_BC;
Call "Solid";
Physical Volume("link_BC") = {vol_};
s_ = link_BG;
Call "Solid";
Physical Volume("link_BG") = {vol_};
s_ = link_CDE;
Call "Solid";
Physical Volume("link_CDE") = {vol_};
s_ = link_EG;
Call "Solid";
Physical Volume("link_EG") = {vol_};
s_ = link_DF;
Call "Solid";
Physical Volume("link_DF") = {vol_};
s_ = link_FGH;
Call "Solid";
Physical Volume("link_FGH") = {vol_};
pin_volumes[] = {};
For i In {0:#pins[] - 1}
  s_ = pins[i];
  Call "Solid";
  pin_volumes[] += vol_;
EndFor
Physical Volume("pins") = {pin_volumes[]};
curves_[] = eye_AB_A[];
Call "Swept";
Physical Surface("eye_AB_A") = {faces_[]};
curves_[] = eye_AB_B[];
Call "Swept";
Physical Surface("eye_AB_B") = {faces_[]};
curves_[] = eye_BC_B[];
Call "Swept";
Physical Surface("eye_BC_B") = {faces_[]};
curves_[] = eye_BC_C[];
Call "Swept";
Physical Surface("eye_BC_C") = {faces_[]};
curves_[] = eye_BG_B[];
Call "Swept";
Physical Surface("eye_BG_B") = {faces_[]};
curves_[] = eye_BG_G[];
Call "Swept";
Physical Surface("eye_BG_G") = {faces_[]};
curves_[] = eye_CDE_C[];
Call "Swept";
Physical Surface("eye_CDE_C") = {faces_[]};
curves_[] = eye_CDE_D[];
Call "Swept";
Physical Surface("eye_CDE_D") = {faces_[]};
curves_[] = eye_CDE_E[];
Call "Swept";
Physical Surface("eye_CDE_E") = {faces_[]};
curves_[] = eye_EG_E[];
Call "Swept";
Physical Surface("eye_EG_E") = {faces_[]};
curves_[] = eye_EG_G[];
Call "Swept";
Physical Surface("eye_EG_G") = {faces_[]};
curves_[] = eye_DF_D[];
Call "Swept";
Physical Surface("eye_DF_D") = {faces_[]};
curves_[] = eye_DF_F[];
Call "Swept";
Physical Surface("eye_DF_F") = {faces_[]};
curves_[] = eye_FGH_F[];
Call "Swept";
Physical Surface("eye_FGH_F") = {faces_[]};
curves_[] = eye_FGH_G[];
Call "Swept";
Physical Surface("eye_FGH_G") = {faces_[]};
curves_[] = pin_B[];
Call "Swept";
Physical Surface("pin_B") = {faces_[]};
curves_[] = pin_C[];
Call "Swept";
Physical Surface("pin_C") = {faces_[]};
curves_[] = pin_D[];
Call "Swept";
Physical Surface("pin_D") = {faces_[]};
curves_[] = pin_E[];
Call "Swept";
Physical Surface("pin_E") = {faces_[]};
curves_[] = pin_F[];
Call "Swept";
Physical Surface("pin_F") = {faces_[]};
curves_[] = pin_G[];
Call "Swept";
Physical Surface("pin_G") = {faces_[]};
curves_[] = foot[];
Call "Swept";
Physical Surface("foot") = {faces_[]};
curves_[] = outline[];
Call "Swept";
Physical Surface("outline") = {faces_[]};
EndIf
