#!/usr/bin/python3
"""Runs the leaf-spring studies of the variable-stiffness servo (seed 002, issue 5) with
postproc/study.py and keeps their tables in cases/leaf_spring/data/ for postproc/leaf_report.py.

    /usr/bin/python3 postproc/leaf_studies.py [--only NAME ...] [--np 2]

About 15 minutes on 2 cores. Each study is one study.py call (a parameter study per load case):
  torsion, bending         one leaf, a = 3, 4, 5 mm x L = 1..5 mm (cases' mesh: nb = 3)
  torsion_long, bending_long  the same leaves 20 and 60 widths long (elongated cells, direct solver)
  coupling                 the four-leaf coupling, a = 3, 4, 5 x L = 1..5, r = 8 mm
  coupling_convergence     a = 4, L = 5: nb = 1, 2, 3, 4 elements through the thickness
  coupling_radius          a = 4, L = 5: r = 4, 8, 12 mm
plus one run whose printed comparison (with the validity warnings, which study.csv does not keep)
is saved as torsion_paper_leaf.txt.
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CASES = os.path.join(ROOT, "cases", "leaf_spring")
DATA = os.path.join(CASES, "data")
P = "Geometry/Parameters/"

WIDTHS = "3,4,5"
LENGTHS = "1,2,3,4,5"
# long leaves: L = 20 a and 60 a (torsion), 20 a (bending); elongated cells, MUMPS
LONG_TORSION = ["--zip", "--vary", P + "a=3,3,4,4,5,5", "--vary", P + "L=60,180,80,240,100,300",
                "--set", P + "nb=2", "--set", P + "aspect=8", "--set", "Linear solver/Method=direct"]
# bending needs shorter cells than torsion for 1 % (aspect 8 overestimates by 0.2 %, see REPORT.md)
LONG_BENDING = ["--zip", "--vary", P + "a=3,4,5", "--vary", P + "L=60,80,100",
                "--set", P + "nb=2", "--set", P + "aspect=4", "--set", "Linear solver/Method=direct"]

STUDIES = {
    "torsion": ("leaf_torsion.prm", ["--vary", P + "a=" + WIDTHS, "--vary", P + "L=" + LENGTHS]),
    "bending": ("leaf_bending.prm", ["--vary", P + "a=" + WIDTHS, "--vary", P + "L=" + LENGTHS]),
    "torsion_long": ("leaf_torsion.prm", LONG_TORSION),
    "bending_long": ("leaf_bending.prm", LONG_BENDING),
    "coupling": ("coupling.prm", ["--vary", P + "a=" + WIDTHS, "--vary", P + "L=" + LENGTHS]),
    "coupling_convergence": ("coupling.prm", ["--vary", P + "nb=1,2,3,4"]),
    "coupling_radius": ("coupling.prm", ["--vary", P + "r=4,8,12"]),
}


def run_study(name, np):
    case, args = STUDIES[name]
    cmd = [sys.executable, os.path.join(ROOT, "postproc", "study.py"), os.path.join(CASES, case),
           "--np", str(np), "--out", os.path.join(DATA, name)] + args
    print("study", name, ":", " ".join(cmd[1:]), flush=True)
    subprocess.run(cmd, check=True)


def save_paper_leaf_comparison(np):
    """The paper's middle leaf (a = 4, L = 5) in torsion, with the printed comparison table."""
    sys.path.insert(0, os.path.join(ROOT, "postproc"))
    from study import run_case
    summary = run_case(os.path.join(CASES, "leaf_torsion.prm"), [], np)
    lines = []
    for c in summary["comparisons"]:
        lines.append("%s ~ %s: FE %.6g, closed form %.6g, %+.2f %%" % (
            c["quantity"], c["closed_form"], c["computed"], c["reference"], 100 * c["relative_difference"]))
        lines += ["  WARNING: " + w for w in c["warnings"]]
    path = os.path.join(DATA, "torsion_paper_leaf.txt")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    print("saved", path)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", nargs="*", choices=sorted(STUDIES) + ["warning"], help="run only these")
    ap.add_argument("--np", type=int, default=2)
    args = ap.parse_args()
    os.makedirs(DATA, exist_ok=True)
    for name in STUDIES:
        if not args.only or name in args.only:
            run_study(name, args.np)
    if not args.only or "warning" in args.only:
        save_paper_leaf_comparison(args.np)


if __name__ == "__main__":
    main()
