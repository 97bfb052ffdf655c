#!/usr/bin/python3
"""Studies survive failures and interruptions (postproc/study.py):

1. A study over the flexure length l = 5, 10, 0 (gmsh cannot build l = 0): the failed point is
   recorded in the table with the solver's message, the two finished points are kept, exit code 3.
2. A 4-point study killed (SIGKILL) after its first point finished resumes with the same command:
   the finished point is read back, not run again, and the final table equals that of an
   uninterrupted run in every column but the measured times and memory (numbers to 1e-9 relative).
3. --point K runs a single point (a scheduler job array); a plain run afterwards collects it.
"""
import csv
import os
import signal
import subprocess
import sys
import tempfile
from case_checks import check, finish

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
study = [sys.executable if os.path.basename(sys.executable).startswith("python") else "/usr/bin/python3",
         os.path.join(root, "postproc", "study.py")]
case = os.path.join(root, "cases", "flexure_hinge.prm")


def table(out):
    with open(os.path.join(out, "study.csv")) as f:
        return list(csv.DictReader(f))


def same_tables(a, b):
    """Equal in every column but measured times and memory; numbers to round-off (1e-9 relative):
    an iterative solve repeated on 2 ranks may differ in its last digits (MUMPS, reduction order)."""
    if len(a) != len(b):
        return False, "%d against %d rows" % (len(a), len(b))
    def scale(row, key):
        # A component that is zero up to round-off (reaction_force_drive_y ~ 5e-12) is compared
        # at the scale of its sibling components (reaction_force_drive_x, ...).
        stem = key.rsplit("_", 1)[0]
        values = []
        for k, v in row.items():
            if k.rsplit("_", 1)[0] == stem:
                try:
                    values.append(abs(float(v)))
                except (TypeError, ValueError):
                    pass
        return max(values + [1e-30])

    for ra, rb in zip(a, b):
        for key in set(ra) | set(rb):
            if key.startswith(("time_", "memory_")):
                continue
            va, vb = ra.get(key), rb.get(key)
            try:
                fa, fb = float(va), float(vb)
                if abs(fa - fb) > 1e-9 * max(abs(fa), abs(fb), scale(ra, key)):
                    return False, "%s: %s against %s" % (key, va, vb)
            except (TypeError, ValueError):
                if va != vb:
                    return False, "%s: %s against %s" % (key, va, vb)
    return True, "every column equal"


base = tempfile.mkdtemp(prefix="study-resume-")

# 1. a failing point
out = os.path.join(base, "failing")
p = subprocess.run(study + [case, "--vary", "Geometry/Parameters/l=5,10,0", "--out", out], capture_output=True, text=True)
rows = table(out) if os.path.exists(os.path.join(out, "study.csv")) else []
statuses = [r["status"] for r in rows]
check(p.returncode == 3 and len(rows) == 3 and statuses[:2] == ["ok", "ok"] and statuses[2].startswith("failed:"),
      "failing point recorded, others kept, exit %d: %s" % (p.returncode, [s[:80] for s in statuses]))
check("rerun the same command" in p.stderr, "the study says how to retry: %s" % p.stderr.strip().splitlines()[-1][:160])

# 2. kill after the first point, resume, compare with an uninterrupted run
vary = ["--vary", "Geometry/Parameters/l=4,6,8,10"]
whole = os.path.join(base, "whole")
subprocess.run(study + [case] + vary + ["--out", whole], check=True, capture_output=True)
killed = os.path.join(base, "killed")
proc = subprocess.Popen(study + [case] + vary + ["--out", killed], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                        text=True, start_new_session=True)
first = proc.stdout.readline()  # printed when the first point is written
os.killpg(proc.pid, signal.SIGKILL)
proc.wait()
points = [f for f in os.listdir(os.path.join(killed, "points")) if f.endswith(".json")]
check(len(points) >= 1 and not [f for f in os.listdir(os.path.join(killed, "points")) if f.endswith(".partial")],
      "killed after '%s': %d finished point(s) kept, no partial file" % (first.strip(), len(points)))
p = subprocess.run(study + [case] + vary + ["--out", killed], capture_output=True, text=True)
resumed = p.stdout.count("(resumed)")
check(p.returncode == 0 and resumed == len(points), "rerun resumes %d point(s) and runs the rest" % resumed)
same, why = same_tables(table(killed), table(whole))
check(same, "resumed table equals the uninterrupted one (%s)" % why)

# 3. one point of a job array, then the collecting run
array = os.path.join(base, "array")
p = subprocess.run(study + [case, "--vary", "Geometry/Parameters/l=4,6", "--out", array, "--point", "1"],
                   capture_output=True, text=True)
p2 = subprocess.run(study + [case, "--vary", "Geometry/Parameters/l=4,6", "--out", array], capture_output=True, text=True)
check(p.returncode == 0 and "(resumed)" in p2.stdout and len(table(array)) == 2,
      "--point 1 runs one point; the collecting run resumes it and runs the other")

subprocess.run(["rm", "-rf", base])
finish()
