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
h = (tf < tw ? tf : tw) / n;
