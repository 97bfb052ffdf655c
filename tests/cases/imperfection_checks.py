#!/usr/bin/python3
"""Geometry/Imperfection: buckling modes shift the geometry, and the path follows the buckled branch.

    imperfection_checks.py column CASE   fixed-free column, its first mode 0.1 at the tip, loaded to
                                         0.9 P_cr: Southwell's plot against Engesser's load
    imperfection_checks.py arch CASE     shallow arch under a force, its first (antisymmetric) mode:
                                         the limit load's drop against Koiter's 2/3-power law

Column (cases/verification/column_imperfection.prm). With an imperfection a in the shape of the
first mode, the tip deflects d = a P / (P_cr - P) to first order (Timoshenko and Gere, Theory of
Elastic Stability, sec. 1.12), so d / P = d / P_cr + a / P_cr: a straight line whose slope and
intercept give P_cr and a (Southwell 1932). Fitted over the steps from 0.3 to 0.9 P_cr it must give
Engesser's load (Euler with the shear correction, 513.22 here) within the issue's 0.5 % (the
converged Q2 linear buckling load is 513.31; the finite-strain critical load lies 0.2 % higher,
514.4, by the shortening before buckling) and the amplitude given within 1 % (measured 0.03 %:
the first-order law's own error is (d / L)^2 < 1e-4 here).

Arch (cases/verification/arch_arc_length.prm, arc length). The perfect arch leaves its symmetric
path at an unstable symmetric bifurcation, so an antisymmetric imperfection a lowers the maximum
load as lambda_b - C a^(2/3) (Koiter 1945; Thompson and Hunt, A General Theory of Elastic
Stability, ch. 3). The fit lambda_b - C a^p over a = 1e-4 ... 3e-3 (0.002-0.06 % of the rise,
4 runs) must give p = 2/3 within 0.02 (measured 0.668-0.670 over several amplitude ranges) and the
perfect arch's bifurcation, as its own arc-length run reports it, within 1e-3 (measured 4.0e-4,
the error of locating a bifurcation between steps), and buckling about the finite-strain state at
0.1425 must find it within 1e-3 too (measured 7.7e-5 of the fit: the linear extrapolation over 1.6e-3). Every imperfect path must report a limit point
and no bifurcation, and a = +-1e-3 must give the same limit load (the arch is symmetric): measured
2e-9, asserted below 6e-9 (the mirrored mesh shift gives mirrored paths, equal up to round-off in
the step sequence).
"""
import math
import os
import sys

import numpy as np
from scipy.optimize import curve_fit

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case, run_case_with_curve  # noqa: E402
from case_checks import check, finish, readme_figure, unknown_mode  # noqa: E402


def engesser_fixed_free(E, nu, H, b, L):
    """Euler's load of a fixed-free column with Engesser's shear correction (kappa = 5/6)."""
    euler = math.pi ** 2 * E * b * H ** 3 / 12 / (4 * L ** 2)
    return euler / (1 + euler / (5.0 / 6.0 * E / (2 * (1 + nu)) * b * H))


def column(case):
    amplitude, force = 0.1, 462.5
    summary, rows = run_case_with_curve(case)
    reference = engesser_fixed_free(200000.0, 0.3, 5.0, 1.0, 100.0)
    loads = np.array([float(r["load_factor"]) * force for r in rows])
    tip = np.array([float(r["displacement_tip_y"]) for r in rows])
    used = loads > 0.3 * reference
    check(used.sum() >= 5, "%d steps between 0.3 and 0.9 P_cr for the fit" % used.sum())
    slope, intercept = np.polyfit(tip[used], tip[used] / loads[used], 1)
    critical, fitted_amplitude = 1 / slope, intercept / slope
    error = critical / reference - 1
    print("Southwell: P_cr %.6g against Engesser %.6g (%+.3f %%), amplitude %.6g against %g"
          % (critical, reference, 100 * error, fitted_amplitude, amplitude))
    check(abs(error) < 0.005, "Southwell's P_cr within 0.5 %% of Engesser's load (%+.3f %%)" % (100 * error))
    check(abs(fitted_amplitude / amplitude - 1) < 0.01,
          "Southwell's amplitude within 1 %% of the imperfection given (%+.3f %%)"
          % (100 * (fitted_amplitude / amplitude - 1)))
    readme_figure(critical, "514.42", "Southwell's P_cr")
    readme_figure(fitted_amplitude, "0.10003", "Southwell's amplitude")
    mode_factor = summary["quantities"]["buckling_factor_1"] * force
    check(abs(mode_factor / reference - 1) < 0.005,
          "the imperfection's linear buckling load %.6g within 0.5 %% of Engesser's" % mode_factor)
    check(tip[-1] > 0, "the tip deflects the way the imperfection leans (+0.1 at the tip): %.4g" % tip[-1])


def arch(case):
    def limit_load(amplitude):
        summary, _ = run_case_with_curve(case, ["Geometry/Imperfection=1: %g" % amplitude])
        q = summary["quantities"]
        check(q["limit_points"] >= 1 and q["bifurcations"] == 0,
              "a = %g: %d limit points, %d bifurcations" % (amplitude, q["limit_points"], q["bifurcations"]))
        return q["limit_point_1"]

    perfect = run_case_with_curve(case)[0]["quantities"]
    check(perfect["bifurcations"] >= 1, "the perfect arch bifurcates (%d)" % perfect["bifurcations"])
    bifurcation = perfect["bifurcation_1"]
    amplitudes = np.array([1e-4, 3e-4, 1e-3, 3e-3])
    loads = np.array([limit_load(a) for a in amplitudes])
    for a, l in zip(amplitudes, loads):
        print("a = %-7g limit load %.8f (drop %.3e)" % (a, l, bifurcation - l))
    check(all(np.diff(loads) < 0) and loads[0] < bifurcation,
          "the limit load falls as the imperfection grows, below the bifurcation %.8f" % bifurcation)
    (critical, scale, power), _ = curve_fit(lambda a, lb, c, p: lb - c * a ** p, amplitudes, loads,
                                            p0=[bifurcation, 0.05, 0.6])
    print("Koiter fit: lambda_b %.8f, exponent %.4f" % (critical, power))
    check(abs(power - 2.0 / 3.0) < 0.02, "the drop goes as a^%.4f, Koiter's a^(2/3) within 0.02" % power)
    check(abs(critical / bifurcation - 1) < 1e-3,
          "the fit's lambda_b %.8f is the perfect arch's bifurcation %.8f within 1e-3 (%.1e)"
          % (critical, bifurcation, critical / bifurcation - 1))
    readme_figure(bifurcation, "0.142785", "the perfect arch's bifurcation")
    readme_figure(power, "0.670", "Koiter fit's exponent")
    readme_figure(critical, "0.142727", "Koiter fit's lambda_b")
    readme_figure(critical / bifurcation - 1, "-4.0e-4", "Koiter fit's lambda_b against the located bifurcation")
    # The same bifurcation by buckling about the finite-strain state just below it (a rigid
    # crown piece in a buckling analysis): measured 0.142716, 1.2e-4 below the fit.
    state = run_case(case, ["Analysis=buckling", "Buckling/Reference load factor=0.1425",
                            "Finite strain/Path=load steps", "Finite strain/Initial step=0.02"])
    about_state = state["quantities"]["buckling_factor_1"]
    check(abs(about_state / critical - 1) < 1e-3,
          "buckling about the state at 0.1425 gives %.8f, the fit's lambda_b within 1e-3 (%.1e)"
          % (about_state, about_state / critical - 1))
    mirrored = limit_load(-1e-3)
    check(abs(mirrored / loads[2] - 1) < 6e-9,  # README: to 2e-9
          "a = -1e-3 gives the limit load of a = +1e-3 (%.10f, %.10f)" % (mirrored, loads[2]))


mode, case = sys.argv[1], sys.argv[2]
if mode == "column":
    column(case)
elif mode == "arch":
    arch(case)
else:
    unknown_mode(mode, ["column", "arch"])
finish()
