// Layers along x for Extrude: n_x cells whose lengths grow by a constant ratio away from the graded
// end(s), the longest grade_x times the shortest. In: n_x, grade_x, graded_ends (0 both ends, 1 the
// start, 2 the far end). Out: layer_count[] (ones), layer_top[] (cumulative fractions, last 1).
// cases/benchmarks/peers/calculix_common.py graded() writes the same grid lines for the peers.
steps = (graded_ends == 0) ? Floor((n_x - 1) / 2) : n_x - 1;
ratio = 1; // gmsh evaluates both branches of ?:, so no 1 / steps there
If (steps > 0)
  ratio = grade_x^(1 / steps);
EndIf
layer_length[] = {}; layer_total = 0;
For i In {0 : n_x - 1}
  k = (graded_ends == 1) ? i : ((graded_ends == 2) ? n_x - 1 - i : ((i < n_x - 1 - i) ? i : n_x - 1 - i));
  layer_length[] += {ratio^k}; layer_total += ratio^k;
EndFor
layer_count[] = {}; layer_top[] = {}; layer_sum = 0;
For i In {0 : n_x - 1}
  layer_sum += layer_length[i]; layer_count[] += {1}; layer_top[] += {layer_sum / layer_total};
EndFor
layer_top[n_x - 1] = 1;
