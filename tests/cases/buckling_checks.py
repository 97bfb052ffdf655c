#!/usr/bin/python3
"""Linearized buckling (Analysis = buckling) against the closed forms of a fixed-free column.

    buckling_checks.py column2d CASE   plane-stress column (L = 100): modes 1-3 against (2n-1)^2 pi^2 E I / (4 L^2)
    buckling_checks.py column3d CASE   3D column (L = 200): weak-axis and strong-axis first modes
    buckling_checks.py ranks    CASE   1 and 2 ranks give the same factors
    buckling_checks.py tension  CASE   the load reversed: factors change sign (the part is pulled)
    buckling_checks.py plate    CASE   a simply supported square plate: the first four doubly symmetric modes

Reference: Euler's load with Engesser's shear correction P = P_E / (1 + P_E / (kappa G A)), kappa =
5/6 (Timoshenko and Gere, Theory of Elastic Stability, sec. 2.18). The Q2 columns are converged in
the mesh (2D: ny = 2, 4, 8 give 513.42, 513.31, 513.28; Q3 513.28), so the bar is the issue's 0.5 %
on the first modes. The third mode of the 2D column is held to 1.5 %: there the shear correction
itself is 4 %, and the plane-stress continuum lies 1.0 % below Engesser's first-order estimate.
Each README figure is also asserted to 3 units of its last stated digit (issue 34): 2D modes 1-3
+0.019 / -0.33 / -0.98 %, 3D weak and strong axis +0.25 / +0.13 %, the strip -0.007 %, about the
column's finite-strain state 514.43 (+0.24 %), linear buckling +0.02 %; on the arch linear buckling
0.053, about the states at 0.03 and 0.033 0.0320 and 0.03333, the limit point 0.033429 (-0.28 %), and
load control stopping between 0.033 and 0.037; the 2D column's mesh study 513.42, 513.31, 513.28.
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case  # noqa: E402
from case_checks import check, finish  # noqa: E402

E, nu = 200000.0, 0.3
G = E / (2 * (1 + nu))
kappa = 5.0 / 6.0


def column_load(n, I, A, L):
    """n-th buckling load of a fixed-free column, Euler with Engesser's shear correction."""
    euler = (2 * n - 1) ** 2 * math.pi ** 2 * E * I / (4 * L ** 2)
    return euler / (1 + euler / (kappa * G * A))


def compare(q, key, reference, bar, what, figure=None, tolerance=None):
    value = q[key]
    error = value / reference - 1
    print("%s: %s = %.6g, closed form %.6g, %+.3f %%" % (what, key, value, reference, 100 * error))
    check(abs(error) < bar, "%s within %.1f %% (%+.3f %%)" % (what, 100 * bar, 100 * error))
    if figure is not None:
        check(abs(error - figure) <= tolerance, "%s: %+.4f %% is the README's %+.3g %% (+- %.2g %%)"
              % (what, 100 * error, 100 * figure, 100 * tolerance))


def readme_value(value, figure, tolerance, what):
    check(abs(value - figure) <= tolerance, "%s: %.6g is the README's %.6g (+- %.2g)" % (what, value, figure, tolerance))


mode, case = sys.argv[1], sys.argv[2]
if mode == "column2d":
    H = 5.0
    q = run_case(case)["quantities"]
    for n, bar, figure, tolerance in ((1, 0.005, 0.00019, 0.00003), (2, 0.005, -0.0033, 0.0003), (3, 0.015, -0.0098, 0.0003)):
        compare(q, "buckling_factor_%d" % n, column_load(n, H ** 3 / 12, H, 100.0), bar, "mode %d" % n, figure, tolerance)
    # README: converged in the mesh, ny = 2, 4 (the case's own), 8 give 513.42, 513.31, 513.28
    for ny, figure in ((2, 513.42), (4, None), (8, 513.28)):
        factor = q["buckling_factor_1"] if figure is None else \
            run_case(case, ["Geometry/Parameters/ny=%d" % ny])["quantities"]["buckling_factor_1"]
        readme_value(factor, figure or 513.31, 0.03, "mode 1 at ny = %d" % ny)
elif mode == "column3d":
    H, W = 10.0, 5.0
    q = run_case(case)["quantities"]
    compare(q, "buckling_factor_1", column_load(1, H * W ** 3 / 12, H * W, 200.0), 0.005, "weak axis", 0.0025, 0.0003)
    # The second factor is the strong axis's first (4 x), below the weak axis's second (9 x).
    compare(q, "buckling_factor_2", column_load(1, W * H ** 3 / 12, H * W, 200.0), 0.005, "strong axis", 0.0013, 0.0003)
elif mode == "ranks":
    one, two = run_case(case, np=1)["quantities"], run_case(case, np=2)["quantities"]
    for k in sorted(one):
        if k.startswith("buckling_factor_"):
            check(abs(one[k] / two[k] - 1) < 1e-8, "%s: 1 rank %.10g, 2 ranks %.10g" % (k, one[k], two[k]))
elif mode == "tension":
    compressed = run_case(case)["quantities"]["buckling_factor_1"]
    pulled = run_case(case, ["Loads/Total force=right: 1 0"])["quantities"]["buckling_factor_1"]
    print("compressed %.6g, pulled %.6g" % (compressed, pulled))
    check(abs(pulled / compressed + 1) < 1e-8, "reversing the load reverses the factor's sign")
elif mode == "strip":
    # Lateral-torsional buckling of a narrow strip (H/W = 10, span 200, fork ends) against
    # (pi/L) sqrt(E I_y G J), the bar 2 %; measured -0.007 % (16 x 4 x 80 cells: -0.071 %).
    q = run_case(case)
    c = next(c for c in q["comparisons"] if c["closed_form"] == "lateral_torsional_buckling_moment")
    print("critical moment %.6g, closed form %.6g" % (c["computed"], c["reference"]))
    check(abs(c["relative_difference"]) < 0.02, "within 2 %% (%+.3f %%)" % (100 * c["relative_difference"]))
    check(abs(c["relative_difference"] + 0.00007) <= 0.00003, "the README's -0.007 %% (+- 0.003 %%): %+.4f %%"
          % (100 * c["relative_difference"]))
    readme_value(c["computed"], 3143.0, 0.3, "critical moment")
    readme_value(c["reference"], 3143.2, 0.3, "closed form")
    check(abs(q["quantities"]["buckling_factor_2"] + q["quantities"]["buckling_factor_1"]) <
          1e-6 * abs(q["quantities"]["buckling_factor_1"]), "the moment reversed buckles the strip the same")
elif mode == "column_state":
    # About the finite-strain state at half the critical load: a straight column deforms linearly before
    # it buckles, so the estimate must agree with Engesser's load and with linear buckling (0.21 % measured).
    H = 5.0
    sets = ["Analysis=buckling", "Loads/Total force=", "Loads/Traction=right: -0.2 0"]
    state = run_case(case, sets + ["Buckling/Reference load factor=256"])["quantities"]
    compare(state, "buckling_factor_1", column_load(1, H ** 3 / 12, H, 100.0), 0.005, "about the state at 256", 0.0024, 0.0003)
    readme_value(state["buckling_factor_1"], 514.43, 0.03, "about the state at 256")
    for reference, figure in ((128, 514.46), (384, 514.41)):  # README: "514.46 and 514.41 at 128 and 384"
        other = run_case(case, sets + ["Buckling/Reference load factor=%d" % reference])["quantities"]
        readme_value(other["buckling_factor_1"], figure, 0.03, "about the state at %d" % reference)
    linear = run_case(case, sets)["quantities"]["buckling_factor_1"]
    check(abs(linear / column_load(1, H ** 3 / 12, H, 100.0) - 1 - 0.0002) <= 0.0003,
          "linear buckling %+.3f %% from Engesser's load, the README's +0.02 %% (+- 0.03 %%)"
          % (100 * (linear / column_load(1, H ** 3 / 12, H, 100.0) - 1)))
    check(abs(state["buckling_factor_1"] / linear - 1) < 0.005, "linear buckling %.6g, about the state %.6g" %
          (linear, state["buckling_factor_1"]))
elif mode == "arch_state":
    # The shallow arch under load: linear buckling ignores the deformation before the snap and is 60 %
    # unconservative; about the state at load factor 0.033 the estimate must find the limit point that
    # arc length follows (0.3 % measured), and be closer to it than about the state at 0.03.
    arc = run_case(case, ["Finite strain/Path=arc length"])["quantities"]["limit_point_1"]
    linear = run_case(case, ["Analysis=buckling"])["quantities"]["buckling_factor_1"]
    near = run_case(case, ["Analysis=buckling", "Buckling/Reference load factor=0.033"])["quantities"]
    far = run_case(case, ["Analysis=buckling", "Buckling/Reference load factor=0.03"])["quantities"]
    print("limit point by arc length %.6g; linear buckling %.6g; about 0.03: %.6g; about 0.033: %.6g" %
          (arc, linear, far["buckling_factor_1"], near["buckling_factor_1"]))
    check(linear / arc - 1 > 0.5, "linear buckling is unconservative here (%+.0f %%)" % (100 * (linear / arc - 1)))
    check(abs(near["buckling_factor_1"] / arc - 1) < 0.005, "about the state at 0.033: %+.2f %% from the limit point" %
          (100 * (near["buckling_factor_1"] / arc - 1)))
    check(abs(near["buckling_factor_1"] - arc) < abs(far["buckling_factor_1"] - arc),
          "the estimate improves as the reference state nears the limit point")
    readme_value(arc, 0.033429, 0.000003, "limit point by arc length")
    readme_value(linear, 0.053, 0.003, "linear buckling")
    readme_value(far["buckling_factor_1"], 0.0320, 0.0003, "about the state at 0.03")
    readme_value(near["buckling_factor_1"], 0.03333, 0.00003, "about the state at 0.033")
    check(abs(near["buckling_factor_1"] / arc - 1 + 0.0028) <= 0.0003, "about the state at 0.033: %+.3f %% from the "
          "limit point, the README's -0.28 %% (+- 0.03 %%)" % (100 * (near["buckling_factor_1"] / arc - 1)))
    # README: "load control stops at 0.033-0.037": the last converged step and the step that failed.
    import re
    import subprocess
    import tempfile
    from study import mpi_env, solver_path
    out = tempfile.mkdtemp(prefix="compliant-arch-")
    p = subprocess.run(["mpirun", "-np", "2", solver_path(), case, "--set", "Output/Directory=" + out],
                       capture_output=True, text=True, env=mpi_env())
    subprocess.run(["rm", "-rf", out])
    stop = re.search(r"stopped at load factor ([0-9.]+) \(last converged step\): the step to ([0-9.]+) failed", p.stderr)
    if check(p.returncode == 3 and stop is not None, "load control stops and says where (exit %d)" % p.returncode):
        readme_value(float(stop.group(1)), 0.033, 0.003, "load control: last converged load factor")
        readme_value(float(stop.group(2)), 0.037, 0.003, "load control: the step that failed")
elif mode == "plate":
    # Square plate a = b = 100, t = 1, simply supported, uniform compression (a quarter, 16 x 16 x 1 Q2).
    # References written out here, not taken from the solver: Kirchhoff, sigma = k pi^2 D / (b^2 t) with
    # k = (m + n^2/m)^2 (Timoshenko and Gere, sec. 9.2), and Mindlin's simply supported plate, which
    # divides it by 1 + pi^2 D ((m/a)^2 + (n/b)^2) / (kappa G t). Bars: the first mode 0.1 % of both (the
    # shear share is 0.056 %); the higher modes 0.5 %, (5, 1) 1 %: its half-wave is 20 cells of 3 here,
    # and it converges from above (32 x 32 x 2: -0.10 % from Mindlin's).
    a = b = 100.0
    t, E_p, nu_p = 1.0, 1000.0, 0.3
    D = E_p * t ** 3 / (12 * (1 - nu_p ** 2))
    G_p = E_p / (2 * (1 + nu_p))

    def plate(m, n, shear):
        kirchhoff = (m + n * n / m) ** 2 * math.pi ** 2 * D / (b ** 2 * t)
        share = math.pi ** 2 * D * ((m / a) ** 2 + (n / b) ** 2) / (kappa * G_p * t) if shear else 0
        return kirchhoff / (1 + share)

    q = run_case(case)["quantities"]
    compare(q, "buckling_factor_1", plate(1, 1, False), 0.001, "mode (1, 1) against Kirchhoff's k = 4", -0.00046, 0.00003)
    for k, (m, n, bar, figure) in enumerate(((1, 1, 0.001, 0.00011), (3, 1, 0.005, 0.0022), (5, 1, 0.01, 0.0073),
                                              (3, 3, 0.005, 0.0010)), start=1):
        compare(q, "buckling_factor_%d" % k, plate(m, n, True), bar, "mode (%d, %d) against Mindlin's" % (m, n),
                figure, 0.0003 if k > 1 else 0.00003)
else:
    sys.exit("FAIL unknown mode " + mode)
finish()
