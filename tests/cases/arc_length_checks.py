#!/usr/bin/python3
"""Arc-length continuation (Finite strain/Path = arc length) against displacement control.

    arc_length_checks.py arch CASE   shallow arch, a force on its rigid crown piece: the arc-length
                                     path against the same arch driven by the crown's displacement

The arch (cases/verification/arch_arc_length.prm) is loaded by a dead force on a rigid crown piece;
driving that piece down by a prescribed displacement with x = 0 (no rotation) is the same problem
on the symmetric path, which the perfect arch keeps under either control. The displacement-driven
curve, force = sum of the support reactions against the crown's deflection, is the reference: at
every arc-length point (deflection w, force lambda F) the reference force at w, by cubic
interpolation between its steps (0.06 apart), must agree with the arc-length force; the two limit
points (load maximum and minimum) must match the reference curve's extrema. Both runs
converge Newton to 1e-9 of the internal forces on the same mesh, so the curves agree far closer
(2e-8 against a cubic spline; 1.2e-6 against the local cubic here, its interpolation error). The
README's figures are asserted to 3 units of their last digit (issue 34): on the curve to 1.2e-6 of
the peak force (bar 1.5e-6), limit loads to 6e-8 and 1.6e-7 of the reference extrema (bars 9e-8
and 1.9e-7), limit points 0.148623 and 0.046270 (to 3e-6), the bifurcations 0.1428 and 0.0508 (to
3e-4), and the cost as an upper bound: 99 steps and 230 Newton
iterations (displacement control 200 and 600), each at most 3 more. The path must pass both limit
points and end at load factor 1 on the inverted branch, with the stability changes reported.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case_with_curve  # noqa: E402
from case_checks import check, finish, unknown_mode  # noqa: E402


def cubic(xs, ys, x):
    """Lagrange cubic through the four points of (xs, ys) nearest x (xs increasing)."""
    i = min(max(next((k for k, v in enumerate(xs) if v >= x), len(xs) - 1) - 2, 0), len(xs) - 4)
    px, py = xs[i:i + 4], ys[i:i + 4]
    total = 0.0
    for j in range(4):
        term = py[j]
        for k in range(4):
            if k != j:
                term *= (x - px[k]) / (px[j] - px[k])
        total += term
    return total


def extremum(xs, ys, index, maximum):
    """Extremum of the cubic interpolant near sample `index`, by golden-section search."""
    a, b = xs[max(index - 1, 0)], xs[min(index + 1, len(xs) - 1)]
    sign = 1 if maximum else -1
    for _ in range(200):
        c, d = b - 0.618034 * (b - a), a + 0.618034 * (b - a)
        if sign * cubic(xs, ys, c) > sign * cubic(xs, ys, d):
            b = d
        else:
            a = c
    return cubic(xs, ys, 0.5 * (a + b))


def force(row):
    return float(row["reaction_force_left_y"]) + float(row["reaction_force_right_y"])


mode, case = sys.argv[1], sys.argv[2]
if mode == "arch":
    arc, arc_rows = run_case_with_curve(case)
    drive = ["Boundary conditions/Rigid=", "Boundary conditions/Displacement=apex: x=0, y=-12",
             "Finite strain/Path=load steps", "Finite strain/Maximum step=0.005",
             "Finite strain/Stability check=false"]
    _, drive_rows = run_case_with_curve(case, drive)
    q = arc["quantities"]
    w_ref = [0.0] + [-float(r["displacement_crown_y"]) for r in drive_rows]
    f_ref = [0.0] + [force(r) for r in drive_rows]
    # the reference's extrema: its first local maximum and the minimum after it
    top = next(i for i in range(1, len(f_ref) - 1) if f_ref[i] >= f_ref[i - 1] and f_ref[i] >= f_ref[i + 1])
    bottom = min(range(top, len(f_ref)), key=lambda i: f_ref[i])
    peak, valley = extremum(w_ref, f_ref, top, True), extremum(w_ref, f_ref, bottom, False)
    print("displacement control: limit loads %.9g and %.9g (%d steps, %d Newton iterations)" %
          (peak, valley, len(drive_rows), sum(int(r["newton_iterations"]) for r in drive_rows)))
    print("arc length: %d steps, %d Newton iterations, %d cutbacks" %
          (q["load_steps"], q["newton_iterations"], q["step_cutbacks"]))
    check(q["load_factor"] == 1.0, "the path ends at load factor 1 (%.12g)" % q["load_factor"])
    worst, imbalance, compared = 0.0, 0.0, 0
    for r in arc_rows:
        w, f = -float(r["displacement_crown_y"]), float(r["load_factor"])
        imbalance = max(imbalance, abs(force(r) - f))
        if w <= w_ref[-1]:
            worst = max(worst, abs(f - cubic(w_ref, f_ref, w)) / peak)
            compared += 1
    # Points past the end of the displacement-controlled curve cannot be compared: at most the last
    # few (the arc-length path ends at load factor 1, the drive at its prescribed displacement).
    check(compared >= len(arc_rows) - 3, "%d of %d arc-length points compared with the displacement-controlled curve"
          % (compared, len(arc_rows)))
    check(imbalance < 1e-9, "support reactions balance the load factor at every step (%.1e)" % imbalance)
    check(worst < 1.5e-6, "arc-length points on the displacement-controlled curve: max force difference "
          "%.2e of the peak force (README 1.2e-6, bar 1.5e-6)" % worst)
    check(q["load_steps"] <= 99 + 3 and q["newton_iterations"] <= 230 + 3,
          "cost at most the README's 99 steps and 230 Newton iterations plus 3 (%d, %d)"
          % (q["load_steps"], q["newton_iterations"]))
    drive_newton = sum(int(r["newton_iterations"]) for r in drive_rows)
    check(len(drive_rows) <= 200 + 3 and drive_newton <= 600 + 3,
          "displacement control at most the README's 200 steps and 600 Newton iterations plus 3 (%d, %d)"
          % (len(drive_rows), drive_newton))
    check(min(float(r["displacement_crown_y"]) for r in arc_rows) < -6.5, "the crown passes the lower limit point")
    check(q.get("limit_points") == 2, "two limit points reported (%s)" % q.get("limit_points"))
    for key, reference, figure, bar in (("limit_point_1", peak, 0.148623, 9e-8), ("limit_point_2", valley, 0.046270, 1.9e-7)):
        error = q[key] / reference - 1
        check(abs(error) < bar, "%s = %.9g against the displacement-controlled extremum %.9g (%+.1e; README "
              "6e-8 and 1.6e-7, bar %.1e)" % (key, q[key], reference, error, bar))
        check(abs(q[key] - figure) <= 3e-6, "%s = %.7f is the README's %.6f (+- 3e-6)" % (key, q[key], figure))
    bifurcations = [q[k] for k in sorted(q) if k.startswith("bifurcation_")]
    print("bifurcations on the symmetric path (asymmetric modes): %s" % ", ".join("%.6g" % b for b in bifurcations))
    check(len(bifurcations) == 2 and all(abs(b - f) <= 3e-4 for b, f in zip(bifurcations, (0.1428, 0.0508))),
          "the two bifurcations are the README's 0.1428 and 0.0508 (+- 3e-4)")
else:
    unknown_mode(mode, ("arch",))
finish()
