#!/usr/bin/python3
"""Mesh convergence of section_torsion on rectangles against the series.

    convergence.py [--ratios 1,2,6,10] [--degrees 1,2] [--n 2,4,8,16] [--cells quads,triangles]
                   [--min-rate R] [--markdown FILE]

Prints, for every ratio a/b, cell type and degree, the relative errors of J, Gamma and tau_max and
the observed orders log2(e(n) / e(2n)) (n = elements across the short side b). With --min-rate the
script fails unless every J order between successive meshes is at least R times min(2 p, 4) and
every J_h >= J (the FE torsion constant is an upper bound). Why min(2 p, 4): J_h - J equals the
squared energy-norm error of omega_h (Galerkin orthogonality), of order h^(2p) for a smooth omega,
but at the corners of a rectangle omega has an r^2 log r term (the Neumann corner exponents of a
90-degree corner are the even integers; the series of omega converges like 1/n^3 there), which
caps the energy-norm order at 2. Measured: 1.9-2.0 (p = 1), 3.6-3.8 (p = 2), 3.9-4.0 (p = 3).
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from section_check import run, series_J, series_tau_max  # noqa: E402
import json  # noqa: E402
import tempfile  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CASE = os.path.join(ROOT, "cases", "section", "rectangle.prm")


def solve(ratio, n, degree, quads):
    b = 1.0
    sets = ["Geometry/Parameters/a=%r" % (ratio * b), "Geometry/Parameters/b=%r" % b,
            "Geometry/Parameters/n=%d" % n, "Geometry/Parameters/quads=%d" % quads,
            "Discretization/Element degree=%d" % degree, "Load/Torque=1"]
    with tempfile.TemporaryDirectory(prefix="section-conv-") as out:
        cmd, proc = run(CASE, sets, out)
        if proc.returncode != 0:
            raise RuntimeError(" ".join(cmd) + "\n" + proc.stderr)
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
    q = s["quantities"]
    d = {c["quantity"]: c["relative_difference"] for c in s["comparisons"]}
    return {"cells": q["n_cells"], "dofs": q["n_dofs"],
            "J": q["torsion_constant"] / series_J(ratio * b, b) - 1,
            "Gamma": d["warping_constant"],
            "tau": q["max_shear_stress"] / series_tau_max(1.0, ratio * b, b) - 1}


def order(e_coarse, e_fine):
    if e_coarse == 0 or e_fine == 0:
        return float("nan")
    return math.log2(abs(e_coarse) / abs(e_fine))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ratios", default="1,2,6,10")
    ap.add_argument("--degrees", default="1,2")
    ap.add_argument("--n", default="2,4,8,16")
    ap.add_argument("--cells", default="quads,triangles")
    ap.add_argument("--min-rate", type=float)
    ap.add_argument("--markdown")
    args = ap.parse_args()
    lines = ["| a/b | cell type | p | n | cells | DoFs | J err | order | Gamma err | order | tau_max err | order |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    failures = []
    for ratio in [float(r) for r in args.ratios.split(",")]:
        for cells in args.cells.split(","):
            for degree in [int(p) for p in args.degrees.split(",")]:
                previous = None
                for n in [int(n) for n in args.n.split(",")]:
                    r = solve(ratio, n, degree, cells == "quads")
                    orders = {k: order(previous[k], r[k]) if previous else float("nan")
                              for k in ("J", "Gamma", "tau")}
                    lines.append("| %g | %s | %d | %d | %d | %d | %+.2e | %.2f | %+.2e | %.2f | %+.2e | %.2f |" % (
                        ratio, cells, degree, n, r["cells"], r["dofs"], r["J"], orders["J"],
                        r["Gamma"], orders["Gamma"], r["tau"], orders["tau"]))
                    print(lines[-1], flush=True)
                    if args.min_rate is not None:
                        # 1e-12: below this the series and the solver's round-off dominate.
                        if r["J"] < -1e-12:
                            failures.append("a/b=%g %s p=%d n=%d: J_h below the series (%+.2e)" % (
                                ratio, cells, degree, n, r["J"]))
                        if previous and abs(previous["J"]) > 1e-10 and \
                                orders["J"] < args.min_rate * min(2 * degree, 4):
                            failures.append("a/b=%g %s p=%d n=%d: J order %.2f < %.2f" % (
                                ratio, cells, degree, n, orders["J"],
                                args.min_rate * min(2 * degree, 4)))
                    previous = r
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n".join(lines) + "\n")
    for f in failures:
        print("FAIL  " + f)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
