#!/usr/bin/python3
"""Runs section_torsion on a case and checks its summary against independent references.

    section_check.py CASE.prm [--set "A/B=v"]... --check "EXPR"... [--expect-error TEXT]

Each --check is a Python expression over q (quantities), p (geometry parameters), d (relative
differences of the closed-form comparisons, keyed "quantity~formula"), rel(x, ref) = x/ref - 1 and
the rectangle series below. Every value used is printed, so a failing test shows what was measured.
--expect-error TEXT: the run must fail with exit code 2 and TEXT in its message.
The executable is $SECTION_TORSION (default: build/solver/fe/section/section_torsion).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def executable():
    return os.environ.get("SECTION_TORSION",
                          os.path.join(ROOT, "build", "solver", "fe", "section", "section_torsion"))


# Timoshenko and Goodier, Theory of Elasticity, 3rd ed., sec. 109, written out here again (not
# taken from closed_forms) so that the test does not share code with the solver's comparison.
def _odd_sum(term, terms=2001):
    return sum(term(n) for n in range(1, terms, 2))


def series_beta(a, b):
    a, b = max(a, b), min(a, b)
    s = _odd_sum(lambda n: math.tanh(n * math.pi * a / (2 * b)) / n ** 5)
    return (1 - 192 / math.pi ** 5 * b / a * s) / 3


def series_J(a, b):
    """Torsion constant beta a b^3 of an a x b rectangle."""
    return series_beta(a, b) * max(a, b) * min(a, b) ** 3


def series_tau_max(T, a, b):
    """Peak shear stress k G theta' b at the middle of the long side, theta' = T / (G J)."""
    a, b = max(a, b), min(a, b)
    # 1/cosh overflows for large n: the terms are negligible long before.
    k = 1 - 8 / math.pi ** 2 * _odd_sum(
        lambda n: 1 / (n * n * math.cosh(min(n * math.pi * a / (2 * b), 700))))
    return k * b * T / series_J(a, b)


def rel(x, ref):
    return x / ref - 1


def run(case, sets, output_dir):
    cmd = [executable(), case, "--set", "Output/Directory=" + output_dir]
    if not any(s.startswith("Output/Fields") for s in sets):
        cmd += ["--set", "Output/Fields=false"]
    for s in sets:
        cmd += ["--set", s]
    return cmd, subprocess.run(cmd, capture_output=True, text=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--check", action="append", default=[])
    ap.add_argument("--expect-error")
    args = ap.parse_args()
    if not args.check and args.expect_error is None:  # nothing checked: fail rather than pass silently
        sys.exit("FAIL neither --check nor --expect-error given")
    with tempfile.TemporaryDirectory(prefix="section-check-") as output_dir:
        cmd, proc = run(args.case, args.set, output_dir)
        if args.expect_error is not None:
            print(" ".join(cmd))
            print("exit code %d, stderr: %s" % (proc.returncode, proc.stderr.strip()))
            ok = proc.returncode == 2 and args.expect_error in proc.stderr
            print(("PASS  " if ok else "FAIL  ") + "exit code 2 and '%s' in the message" % args.expect_error)
            sys.exit(0 if ok else 1)
        if proc.returncode != 0:
            print(" ".join(cmd))
            print(proc.stdout, proc.stderr)
            sys.exit(1)
        print(proc.stdout)
        with open(os.path.join(output_dir, "summary.json")) as f:
            summary = json.load(f)
    q = summary["quantities"]
    p = summary["parameters"]
    d = {c["quantity"] + "~" + c["closed_form"]: c["relative_difference"]
         for c in summary["comparisons"]}
    names = {"math": math, "abs": abs, "rel": rel, "series_J": series_J,
             "series_beta": series_beta, "series_tau_max": series_tau_max}
    failed = 0
    for check in args.check:
        ok = eval(check, names, {"q": q, "p": p, "d": d, "settings": summary["settings"]})
        print(("PASS  " if ok else "FAIL  ") + check)
        failed += not ok
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
