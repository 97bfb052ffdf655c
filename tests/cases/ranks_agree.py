#!/usr/bin/python3
"""Runs a case on 1 and 2 MPI ranks; every quantity of interest must agree to the solver
tolerance. The solve is tightened to a residual reduction of 1e-13 and the quantities must agree
to 1e-8 of the largest quantity of the same kind (a reaction that is zero in theory is compared
with the largest reaction, not with itself)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case  # noqa: E402

case = sys.argv[1]
tight = ["Linear solver/Relative tolerance=1e-13"]
one, two = run_case(case, tight, np=1)["quantities"], run_case(case, tight, np=2)["quantities"]


def kind(key):
    return "_".join(key.split("_")[:2])


scales = {}
for key, value in list(one.items()) + list(two.items()):
    scales[kind(key)] = max(scales.get(kind(key), 0.0), abs(value))
skip = ("time_", "n_ranks", "solver_", "memory_")  # cost figures, not results
bad = 0
for key in sorted(one):
    if key.startswith(skip):
        continue
    a, b = one[key], two[key]
    ok = abs(a - b) <= 1e-8 * max(scales[kind(key)], 1e-300)
    print("%-5s %-40s 1 rank %.12g   2 ranks %.12g" % ("ok" if ok else "DIFF", key, a, b))
    bad += not ok
sys.exit(1 if bad else 0)
