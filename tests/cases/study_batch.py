#!/usr/bin/python3
"""A study's points in one solver process (postproc/study.py batches, `compliant --points`, issue 30
item 3) give what point-by-point runs give:

1. A 9-point study over the flexure length l with a point gmsh cannot build (l = 0) in the middle:
   batched (the default) and one process per point (--batch 1) give equal tables (every quantity to
   1e-9 relative, a component against the largest component of its quantity; times and memory aside), the failed point recorded with the .geo's own message in
   both, the points after it run, exit code 3.
2. `compliant --points` directly: a point with an unknown parameter fails alone (its status line
   names the parameter), leaves no output directory, and the points after it run.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile
from case_checks import check, finish

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
study = ["/usr/bin/python3", os.path.join(root, "postproc", "study.py")]
case = os.path.join(root, "cases", "flexure_hinge.prm")
base = tempfile.mkdtemp(prefix="study-batch-")


def table(out):
    path = os.path.join(out, "study.csv")
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


vary = ["--vary", "Geometry/Parameters/l=4,5,6,7,0,8,9,10,11"]
runs = {}
for name, extra in (("batched", []), ("separate", ["--batch", "1"])):
    out = os.path.join(base, name)
    p = subprocess.run(study + [case] + vary + ["--out", out] + extra, capture_output=True, text=True)
    rows = table(out)
    statuses = [r["status"] for r in rows]
    check(p.returncode == 3 and len(rows) == 9 and statuses.count("ok") == 8 and statuses[4].startswith("failed:")
          and "flexure_hinge_2d.geo: need l > 0" in statuses[4],
          "%s: l = 0 failed with the .geo's message, the 8 others ran, exit %d: %s"
          % (name, p.returncode, statuses[4][:120] if len(statuses) > 4 else statuses))
    runs[name] = rows

def kind_scale(row, key):
    """The largest magnitude among the row's components of the same quantity (reaction_force_base_x, _y):
    a component that is round-off of it (a reaction in a direction nothing loads, 1e-11 beside 0.03) is
    compared against that scale, since its own digits depend on the heap's layout (the alignment of small
    vectors changes the rounding of vectorized sums), which a process that ran other points before has
    laid out differently."""
    stem = re.sub(r"_[xyz]$", "", key)
    scale = 0.0
    for k, v in row.items():
        if re.sub(r"_[xyz]$", "", k) == stem:
            try:
                scale = max(scale, abs(float(v)))
            except (TypeError, ValueError):
                pass
    return scale


worst = 0.0
for a, b in zip(runs["batched"], runs["separate"]):
    for key in a:
        if key.startswith(("time_", "memory_")) or a[key] == b.get(key):
            continue
        try:
            fa, fb = float(a[key]), float(b[key])
            worst = max(worst, abs(fa - fb) / max(abs(fa), abs(fb), kind_scale(a, key)))
        except (TypeError, ValueError):
            worst = float("inf")
check(len(runs["batched"]) == len(runs["separate"]) and worst <= 1e-9,
      "batched and separate tables equal (largest relative difference %.2g)" % worst)

points = os.path.join(base, "points.txt")
with open(points, "w") as f:
    f.write("%s/p0\tGeometry/Parameters/t=0.4\n" % base)
    f.write("%s/p1\tGeometry/Parameters/no_such=1\n" % base)
    f.write("%s/p2\tGeometry/Parameters/t=0.45\n" % base)
p = subprocess.run(["mpirun", "-np", "2", solver_path(), case, "--points", points], capture_output=True, text=True,
                   env=mpi_env())
status = open(points + ".status").read().splitlines() if os.path.exists(points + ".status") else []
check(p.returncode == 3 and len(status) == 3 and status[0] == "0\tok" and status[2] == "2\tok"
      and status[1].startswith("1\tfailed\t") and "no_such" in status[1],
      "--points: the bad point fails alone, exit %d: %s" % (p.returncode, status))
check(os.path.exists(os.path.join(base, "p0", "summary.json")) and os.path.exists(os.path.join(base, "p2", "summary.json"))
      and not os.path.exists(os.path.join(base, "p1")), "--points: summaries of the good points, no output of the bad one")

subprocess.run(["rm", "-rf", base])
finish()
