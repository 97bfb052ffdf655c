#!/usr/bin/python3
"""Runs a case and checks its summary against independent references.

    run_case.py CASE.prm [--np N] [--set "A/B=v"]... --check "EXPR"...

Each --check is a Python expression over q (quantities), p (geometry parameters),
d (relative differences of the closed-form comparisons, keyed "quantity~formula") and w (their
validity warnings, one text per comparison, keyed the same way). Every value
used is printed, so a failing test shows what was measured.
"""
import argparse
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--check", action="append", default=[])
    args = ap.parse_args()
    if not args.check:  # a run with nothing checked verifies nothing: fail rather than pass silently
        sys.exit("FAIL no --check given")
    summary = run_case(args.case, args.set, args.np)
    q = summary["quantities"]
    p = summary["parameters"]
    d = {c["quantity"] + "~" + c["closed_form"]: c["relative_difference"] for c in summary["comparisons"]}
    w = {c["quantity"] + "~" + c["closed_form"]: "; ".join(c["warnings"]) for c in summary["comparisons"]}
    for c in summary["comparisons"]:
        print("%-40s FE %-14.8g %-45s %-14.8g diff %+.3f %%  %s" % (
            c["quantity"], c["computed"], c["closed_form"], c["reference"],
            100 * c["relative_difference"], "; ".join(c["warnings"])))
    failed = 0
    for check in args.check:
        ok = eval(check, {"math": math, "abs": abs}, {"q": q, "p": p, "d": d, "w": w})
        print(("PASS  " if ok else "FAIL  ") + check)
        failed += not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
