#!/usr/bin/python3
"""The bistable double beam (cases/bistable/double_beam.prm, issue 27 item 4) under a force.

    bistable_checks.py converged CASE

The arc-length run must pass both limit points and reach load factor 1 on the second stable
branch; forward and pull-back switching forces and the second stable position, from curve.csv, must
agree within 1 % with the same switch on a mesh twice as fine along the beams (the issue's bar for
mesh convergence); the second stable position lies near the mirror image of the first (an
inextensible beam's is exactly 2h; stretching and the block move it less than 3 % inside); the
limit points in the summary agree with the curve's extrema. The closed-form comparison
(Qiu-Lang-Slocum, large-Q limits) is printed with its validity warning, not asserted: at Q = 8
they lie 6 and 16 % above this switch (cases/bistable/REPORT.md).
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
from study import run_case_with_curve  # noqa: E402
from bistable_switch import analyse  # noqa: E402
from case_checks import check, finish, unknown_mode  # noqa: E402

mode, case = sys.argv[1], sys.argv[2]
L, h, t = 400.0, 8.0, 1.0
push = 3 * 2 * 740 * 1000 * t ** 3 / 12 * h / L ** 3  # the case's force (twice the estimate, three times over)


def switch(sets, label):
    summary, rows = run_case_with_curve(case, sets)
    r = analyse(rows, lambda row: float(row["load_factor"]) * push, lambda row: -float(row["rigid_displacement_pad_y"]))
    q = summary["quantities"]
    print("%s: %d DoFs, %d steps, F_top %.6g, F_bottom %.6g, middle %.5g, second %.5g, barrier %.5g" %
          (label, q["n_dofs"], q["load_steps"], r["force_top"], r["force_bottom"], r["stroke_middle"] or -1,
           r["stroke_second"] or -1, r["barrier"] or -1))
    for c in summary["comparisons"]:
        print("  %s ~ %s: %.6g against %.6g (%+.1f %%)%s" % (c["quantity"], c["closed_form"], c["computed"],
              c["reference"], 100 * c["relative_difference"], "; " + "; ".join(c.get("warnings", [])) if c.get("warnings") else ""))
    return q, r


if mode == "converged":
    q, coarse = switch([], "case mesh (n = 100)")
    check(q["load_factor"] == 1.0 and q.get("limit_points") == 2, "the path passes both limit points to load factor 1")
    check(coarse["stroke_second"] is not None, "the second stable position is reached")
    check(abs(q["limit_point_1"] * push / coarse["force_top"] - 1) < 1e-3,
          "limit_point_1 is the curve's maximum (%.6g, %.6g)" % (q["limit_point_1"] * push, coarse["force_top"]))
    check(abs(-q["limit_point_2"] * push / coarse["force_bottom"] - 1) < 1e-3,
          "limit_point_2 is the curve's minimum (%.6g, %.6g)" % (-q["limit_point_2"] * push, coarse["force_bottom"]))
    second = coarse["stroke_second"]
    check(0.97 * 2 * h < second <= 2 * h, "second stable position %.4g = %.4f x 2h" % (second, second / (2 * h)))
    # The README's figures, each to 3 units of its last digit: forward 696.6 and pull-back 310.7
    # E I h / L^3 per beam, second stable position 0.984 of 2h.
    unit = 1000 * t ** 3 / 12 * h / L ** 3
    for what, value, figure, tolerance in (("forward switching force per beam", coarse["force_top"] / 2 / unit, 696.6, 0.3),
                                           ("pull-back switching force per beam", abs(coarse["force_bottom"]) / 2 / unit, 310.7, 0.3),
                                           ("second stable position / 2h", second / (2 * h), 0.984, 0.003)):
        check(abs(value - figure) <= tolerance, "%s %.5g is the README's %.4g (+- %.1g)" % (what, value, figure, tolerance))
    _, fine = switch(["Geometry/Parameters/n=200"], "fine mesh (n = 200)")
    for key in ("force_top", "force_bottom", "stroke_second", "barrier"):
        change = coarse[key] / fine[key] - 1
        check(abs(change) < 0.01, "%s converged: n = 100 %.6g, n = 200 %.6g (%+.3f %%)" %
              (key, coarse[key], fine[key], 100 * change))
        if key != "barrier":  # README: "mesh-converged to 0.02 %" (the forces and the stable position)
            check(abs(change) <= 0.0005, "%s: n = 100 within the README's 0.02 %% (+ 3 units: 0.05 %%) of n = 200 (%+.3f %%)"
                  % (key, 100 * change))
else:
    unknown_mode(mode, ("converged",))
finish()
