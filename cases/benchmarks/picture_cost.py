#!/usr/bin/python3
"""What the pictures and report.html cost (issue 32: under 10 % of the run's time on the default case).

Runs a case (default cases/flexure_hinge.prm, 2 ranks) REPEATS times with Output/Pictures=true and
=false, alternating so that a busy machine hurts both alike, and prints the median wall time of the
whole run (mpirun to exit) of each, their difference, and the drawing time the run itself prints
("pictures and page X s"). Writes picture_cost.md beside this script with --write.

  /usr/bin/python3 cases/benchmarks/picture_cost.py [--case CASE] [--repeats N] [--write] [--set S ...]
"""
import argparse
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
sys.path.insert(0, os.path.join(root, "postproc"))
from study import mpi_env, solver_path  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--case", default=os.path.join(root, "cases", "flexure_hinge.prm"))
parser.add_argument("--repeats", type=int, default=7)
parser.add_argument("--ranks", type=int, default=2)
parser.add_argument("--set", action="append", default=[])
parser.add_argument("--write", action="store_true")
args = parser.parse_args()

times = {"true": [], "false": []}
cpu = {"true": [], "false": []}
drawing = []
sizes = {}
for r in range(args.repeats):
    for pictures in ("true", "false"):
        out = tempfile.mkdtemp(prefix="picture-cost-")
        command = ["mpirun", "-np", str(args.ranks), solver_path(), args.case, "--set", "Output/Directory=" + out,
                   "--set", "Output/Pictures=" + pictures]
        for s in args.set:
            command += ["--set", s]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        proc = subprocess.run(command, capture_output=True, text=True, env=mpi_env())
        elapsed = time.perf_counter() - start
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu[pictures].append(after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime)
        if proc.returncode != 0:
            sys.exit("run failed: " + proc.stderr[-500:])
        times[pictures].append(elapsed)
        m = re.search(r"pictures and page ([0-9.eE+-]+) s", proc.stdout)
        if pictures == "true" and m:
            drawing.append(float(m.group(1)))
            sizes = {f: os.path.getsize(os.path.join(out, f)) for f in sorted(os.listdir(out))}
        shutil.rmtree(out)

with_p, without = statistics.median(times["true"]), statistics.median(times["false"])
cpu_with, cpu_without = statistics.median(cpu["true"]), statistics.median(cpu["false"])
lines = [
    "# Picture and report cost",
    "",
    "`/usr/bin/python3 cases/benchmarks/picture_cost.py --case %s --repeats %d%s` (%d ranks, median of %d "
    "alternating runs each, wall time of the whole run from mpirun to exit):"
    % (os.path.relpath(args.case, root), args.repeats, "".join(" --set '%s'" % s for s in args.set),
       args.ranks, args.repeats),
    "",
    "| | median wall time | median CPU time (all processes) |",
    "|---|---|---|",
    "| `Output/Pictures = true` | %.3f s | %.3f s |" % (with_p, cpu_with),
    "| `Output/Pictures = false` | %.3f s | %.3f s |" % (without, cpu_without),
    "| difference | %+.3f s (%+.1f %%) | %+.3f s (%+.1f %%) |" % (with_p - without, 100 * (with_p - without) / without,
                                                   cpu_with - cpu_without, 100 * (cpu_with - cpu_without) / cpu_without),
    "| drawing + writing, as the run times it (median) | %.4f s (%.2f %% of the run) |"
    % (statistics.median(drawing), 100 * statistics.median(drawing) / with_p),
    "",
    "Files of one run: " + ", ".join("%s %d B" % (f, s) for f, s in sizes.items()) + ".",
    "",
    "On a machine shared with other jobs the wall times scatter by more than the drawing costs; the "
    "CPU times and the run's own figure are the steadier measures.",
    "",
    "All runs (s): with %s; without %s." % (" ".join("%.2f" % t for t in times["true"]),
                                             " ".join("%.2f" % t for t in times["false"])),
]
print("\n".join(lines))
if args.write:
    open(os.path.join(here, "picture_cost.md"), "w").write("\n".join(lines) + "\n")
