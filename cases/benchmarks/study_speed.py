#!/usr/bin/python3
"""Speed of a parameter study (issue 30, item 3): the 2D flexure hinge at its default mesh over
--points values of the flexure thickness t (0.3 to 0.5 mm), run three ways by postproc/study.py:

  point by point   --batch 1 --np 2: a solver process per point (what a study did before batches)
  batched          --np 2: up to 50 points per process (`compliant --points`)
  batched, 2 jobs  --np 1 --jobs 2: two single-rank processes at once, each with its batches

Prints points per second of each and the largest relative difference of any quantity from the
point-by-point table (1 rank against 2 differs at the iterative solver's tolerance); writes
study_speed.md beside this script.

    /usr/bin/python3 cases/benchmarks/study_speed.py [--points 200]
"""
import argparse
import csv
import os
import subprocess
import tempfile
import time

from report_header import provenance

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
STUDY = ["/usr/bin/python3", os.path.join(ROOT, "postproc", "study.py"), os.path.join(ROOT, "cases", "flexure_hinge.prm")]


def run(points, extra, out):
    start = time.time()
    p = subprocess.run(STUDY + ["--vary", "Geometry/Parameters/t=0.3:0.5:%d" % points, "--out", out] + extra,
                       capture_output=True, text=True)
    seconds = time.time() - start
    rows = list(csv.DictReader(open(os.path.join(out, "study.csv"))))
    return p.returncode, seconds, rows


def largest_difference(a, b):
    """Largest relative difference of any quantity and its name; a component is compared at the
    scale of its largest sibling (reaction_force_base_y ~ 1e-11 beside _x ~ 1e-2 is round-off);
    times, memory, the rank count and the diff: columns (differences of the quantities) aside."""
    worst, where = 0.0, ""
    for ra, rb in zip(a, b):
        for key in ra:
            if key.startswith(("time_", "memory_", "solver_", "diff:")) or key == "n_ranks" or ra[key] == rb.get(key):
                continue
            try:
                stem = key.rsplit("_", 1)[0]
                scale = max(abs(float(v)) for k, v in ra.items() if k.rsplit("_", 1)[0] == stem and _number(v))
                d = abs(float(ra[key]) - float(rb[key])) / max(scale, 1e-300)
            except (TypeError, ValueError):
                d = float("inf")
            if d > worst:
                worst, where = d, key
    return worst, where


def _number(v):
    try:
        float(v)
        return True
    except (TypeError, ValueError):
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--points", type=int, default=200)
    ap.add_argument("--out", default=HERE, help="folder for study_speed.md")
    args = ap.parse_args()
    work = tempfile.mkdtemp(prefix="study-speed-")
    ways = [("point by point (--batch 1, 2 ranks)", ["--batch", "1"]),
            ("batched (2 ranks)", []),
            ("batched, 2 jobs of 1 rank", ["--np", "1", "--jobs", "2"])]
    results = []
    for k, (name, extra) in enumerate(ways):
        code, seconds, rows = run(args.points, extra, os.path.join(work, "w%d" % k))
        ok = sum(r["status"] == "ok" for r in rows)
        results.append((name, code, seconds, rows, ok))
        print("%-38s %4d of %d points ok, %7.1f s, %5.2f points/s" % (name, ok, args.points, seconds, ok / seconds),
              flush=True)
    lines = ["# Parameter study speed (issue 30, item 3)", ""] + provenance() + [
             "The 2D flexure hinge (`cases/flexure_hinge.prm`, default mesh, about 1.3-3.3k DoFs) over %d "
             "values of t from 0.3 to 0.5 mm, whole study wall time by `postproc/study.py`." % args.points, "",
             "| way | points ok | seconds | points per second | speed-up |", "|---|---|---|---|---|"]
    for name, code, seconds, rows, ok in results:
        lines.append("| %s | %d | %.1f | %.2f | %.1f |" % (name, ok, seconds, ok / seconds, results[0][2] / seconds))
    for name, code, seconds, rows, ok in results[1:]:
        worst, where = largest_difference(results[0][3], rows)
        lines.append("")
        lines.append("%s against point by point: largest relative difference of any quantity %.1e (%s; a "
                     "component at the scale of its siblings)." % (name, worst, where))
        print("%s: largest relative difference %.1e (%s)" % (name, worst, where))
    open(os.path.join(args.out, "study_speed.md"), "w").write("\n".join(lines) + "\n")
    subprocess.run(["rm", "-rf", work])


if __name__ == "__main__":
    main()
