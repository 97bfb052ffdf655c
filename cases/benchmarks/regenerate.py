#!/usr/bin/python3
"""Regenerates every benchmark report in this folder with one command (issue 30, item 4): each
benchmark runs with the arguments its committed report was made with, one after another (they
share the machine and must not overlap), and writes its .md (table, fitted slopes, the comparison
at equal accuracy where peers take part), .csv and chart, each headed by the command, the machine
and the versions of this solver, its libraries and the peers (report_header.py).

  bash scripts/setup.sh peers                                   # once: FEniCSx and CalculiX
  /usr/bin/python3 cases/benchmarks/regenerate.py               # all of them, several hours on 2 cores
  /usr/bin/python3 cases/benchmarks/regenerate.py --only cantilever,study
  /usr/bin/python3 cases/benchmarks/regenerate.py --quick --out /tmp/bench   # the smallest meshes: a check
  /usr/bin/python3 cases/benchmarks/regenerate.py --list

--quick runs every benchmark on its smallest meshes into --out (default a new temporary folder),
so that the committed reports are not overwritten by figures that do not represent them.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3"

# name: (script, full arguments, quick arguments, peers it needs, what it writes, minutes on 2 cores).
# The cantilever's tip is a node of the 20-node peer mesh for even n only.
BENCHMARKS = {
    "cantilever": ("speed_vs_peers.py", ["--problem", "cantilever"],
                   ["--problem", "cantilever", "--n", "2,4", "--methods", "auto"], ["fenicsx", "calculix"],
                   "cantilever_speed.{md,csv,png}", 60),
    "leaf": ("speed_vs_peers.py", ["--problem", "leaf"],
             ["--problem", "leaf", "--n", "1,2,3", "--methods", "auto"], ["fenicsx", "calculix"],
             "leaf_speed.{md,csv,png}", 40),
    "hinge": ("speed_vs_peers.py", ["--problem", "hinge"],
              ["--problem", "hinge", "--n", "2,3,4", "--methods", "auto"], ["fenicsx", "calculix"],
              "hinge_speed.{md,csv,png}", 40),
    "flexure-finite-strain": ("speed_vs_peers.py", ["--problem", "flexure-finite-strain", "--methods", "auto,direct"],
                              ["--problem", "flexure-finite-strain", "--n", "1,2", "--methods", "auto"], ["fenicsx", "calculix"],
                              "flexure-finite-strain_speed.{md,csv,png}", 90),
    "finite-strain": ("finite_strain_speed.py", [], ["--meshes", "20x4x1,40x8x2", "--methods", "matrix-free"],
                      [], "finite_strain_speed.{md,csv,png}", 15),
    "buckling": ("buckling_speed.py", ["--m", "1,2,3,4", "--reference-m", "5", "--elements", "C3D20R,C3D20",
                                       "--ranks", "2"],
                 ["--m", "1,2,3", "--reference-m", "4", "--elements", "C3D20R", "--ranks", "2"], ["calculix"],
                 "buckling_speed.{md,csv}", 20),
    "memory": ("memory_per_rank.py", [], ["--n", "4", "--ranks", "1,2"], [], "memory_per_rank.{md,csv}", 10),
    "study": ("study_speed.py", ["--points", "200"], ["--points", "20"], [], "study_speed.md", 5),
    "simd": ("simd_speed.py", [], ["--repeat", "1"], [], "simd_speed.md", 25),
}


def peer_missing(peer):
    if peer == "calculix":
        return shutil.which("ccx") is None
    if peer == "fenicsx":
        return subprocess.run([PYTHON, "-c", "import dolfinx"], capture_output=True).returncode != 0
    return False


def output_arguments(script, out):
    """Where each script writes, when it is not this folder."""
    if script == "finite_strain_speed.py":
        return ["--output", os.path.join(out, "finite_strain_speed")]
    return ["--out", out]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--only", default="", help="comma-separated names (--list shows them); default all")
    ap.add_argument("--quick", action="store_true", help="smallest meshes only, into --out: a check of the chain")
    ap.add_argument("--out", default=None, help="folder for the reports (default: this folder; --quick: a new "
                    "temporary one)")
    ap.add_argument("--list", action="store_true")
    args = ap.parse_args()
    names = [n for n in args.only.split(",") if n] or list(BENCHMARKS)
    unknown = [n for n in names if n not in BENCHMARKS]
    if unknown:
        sys.exit("regenerate.py: unknown benchmark(s) %s; expected some of %s" % (", ".join(unknown),
                                                                                  ", ".join(BENCHMARKS)))
    if args.list:
        for name, (script, full, quick, peers, writes, minutes) in BENCHMARKS.items():
            print("%-14s %-22s writes %-32s peers %-18s about %d min" % (name, script, writes,
                                                                          ",".join(peers) or "-", minutes))
        return 0
    missing = sorted({p for n in names for p in BENCHMARKS[n][3] if peer_missing(p)})
    if missing:
        sys.exit("regenerate.py: peer(s) %s not installed: run 'bash scripts/setup.sh peers' first, or leave "
                 "out the benchmarks that need them with --only" % ", ".join(missing))
    out = args.out or (tempfile.mkdtemp(prefix="benchmarks-") if args.quick else HERE)
    os.makedirs(out, exist_ok=True)
    failed, start = [], time.time()
    for name in names:
        script, full, quick, peers, writes, minutes = BENCHMARKS[name]
        cmd = [PYTHON, os.path.join(HERE, script)] + (quick if args.quick else full) + output_arguments(script, out)
        print("== %s: %s" % (name, " ".join(cmd)), flush=True)
        began = time.time()
        code = subprocess.run(cmd).returncode
        print("== %s: exit %d after %.1f min" % (name, code, (time.time() - began) / 60), flush=True)
        if code != 0:
            failed.append(name)
    print("Reports in %s; %d of %d benchmarks done in %.1f min%s" % (
        out, len(names) - len(failed), len(names), (time.time() - start) / 60,
        "; failed: " + ", ".join(failed) if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
