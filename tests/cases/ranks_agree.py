#!/usr/bin/python3
"""Runs a case on 1 and 2 MPI ranks; every quantity of interest must agree to the solver
tolerance. The solve is tightened to a residual reduction of 1e-13 and the quantities must agree
to 1e-8 of the largest quantity of the same kind (a reaction that is zero in theory is compared
with the largest reaction, not with itself).

  ranks_agree.py <case> [--set-both Section/Name=value ...] [--set Section/Name=value ...]
                 [--expect setting=value ...]

--set-both applies to both runs; --set applies to the 2-rank run only (e.g. Discretization/Mesh partition=distributed: each rank
then holds only its part of the mesh); --expect checks a setting of its summary.json."""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("case")
parser.add_argument("--set", action="append", default=[], dest="sets")
parser.add_argument("--set-both", action="append", default=[], dest="common")
parser.add_argument("--expect", action="append", default=[])
args = parser.parse_args()

tight = ["Linear solver/Relative tolerance=1e-13"] + args.common
one = run_case(args.case, tight, np=1)["quantities"]
summary_two = run_case(args.case, tight + args.sets, np=2)
two = summary_two["quantities"]


def kind(key):
    return "_".join(key.split("_")[:2])


scales = {}
for key, value in list(one.items()) + list(two.items()):
    scales[kind(key)] = max(scales.get(kind(key), 0.0), abs(value))
# Cost figures, not results (a Newton count may differ by one where rounding meets the tolerance).
skip = ("time_", "n_ranks", "solver_", "memory_", "newton_iterations", "linear_solves")
bad = 0
for key in sorted(one):
    if key.startswith(skip):
        continue
    # Where a peak lies is ambiguous when symmetric points tie (the clamped corners of a
    # cantilever): its value is compared, not its location.
    if key[-2:] in ("_x", "_y", "_z") and key[:-2] in one and "max" in key[:-2]:
        continue
    if key not in two:
        print("MISSING %-38s on 2 ranks" % key)
        bad += 1
        continue
    a, b = one[key], two[key]
    ok = abs(a - b) <= 1e-8 * max(scales[kind(key)], 1e-300)
    print("%-5s %-40s 1 rank %.12g   2 ranks %.12g" % ("ok" if ok else "DIFF", key, a, b))
    bad += not ok
for expectation in args.expect:
    name, value = expectation.split("=", 1)
    got = summary_two["settings"].get(name)
    print("%-5s setting %s = %s (expected %s)" % ("ok" if got == value else "DIFF", name, got, value))
    bad += got != value
sys.exit(1 if bad else 0)
