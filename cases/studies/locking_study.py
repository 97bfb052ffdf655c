#!/usr/bin/python3
"""Volumetric locking study: Cook's membrane, plane strain, compressible neo-Hookean at finite
strain (cases/verification/cook_membrane_neo_hooke.prm switched to plane strain and the
mixed-capable neo-Hookean law, E fixed), Poisson's ratio rising to
0.4999, for displacement-only Q1 and Q2 and the mixed Q1-P0 and Q2-P1 formulations. Prints the
table of the corner displacement and writes study.csv and locking.png.

    /usr/bin/python3 cases/studies/locking_study.py [--n 8] [--out results/locking]
"""
import argparse
import csv
import os
import sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(root, "postproc"))
from study import run_case  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--n", type=int, default=8, help="elements per side")
ap.add_argument("--out", default=os.path.join("results", "locking"))
ap.add_argument("--nus", default="0.3,0.45,0.49,0.499,0.4999")
args = ap.parse_args()
case = os.path.join(root, "cases", "verification", "cook_membrane_neo_hooke.prm")
variants = [("Q1 displacement", 1, "displacement"), ("Q2 displacement", 2, "displacement"),
            ("Q1-P0 mixed", 1, "mixed"), ("Q2-P1 mixed", 2, "mixed")]
nus = [float(v) for v in args.nus.split(",")]
os.makedirs(args.out, exist_ok=True)
rows = []
print("%-8s" % "nu" + "".join("%18s" % v[0] for v in variants))
for nu in nus:
    row = {"nu": nu}
    for name, degree, formulation in variants:
        try:
            q = run_case(case, ["Model=plane strain", "Finite strain/Law=neo-Hookean",
                                "Geometry/Parameters/n=%d" % args.n, "Discretization/Element degree=%d" % degree,
                                "Finite strain/Formulation=" + formulation,
                                "Material/Materials=*: steel, E=1.0985, nu=%g" % nu])["quantities"]
            row[name] = q["displacement_corner_y"]
        except RuntimeError as e:
            row[name] = float("nan")
            print("  %s at nu=%g failed: %s" % (name, nu, str(e).splitlines()[-1]))
    rows.append(row)
    print("%-8g" % nu + "".join("%18.4f" % row[v[0]] for v in variants), flush=True)

with open(os.path.join(args.out, "study.csv"), "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    w.writeheader()
    w.writerows(rows)
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for name, _, _ in variants:
        ax.semilogx([0.5 - r["nu"] for r in rows], [r[name] for r in rows], "o-", label=name)
    ax.invert_xaxis()
    ax.set_xlabel("0.5 - nu")
    ax.set_ylabel("corner displacement (mm)")
    ax.set_title("Cook's membrane, plane strain neo-Hookean, %d x %d cells" % (args.n, args.n))
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "locking.png"), dpi=110)
except ImportError:
    pass
print("table and chart in", args.out)
