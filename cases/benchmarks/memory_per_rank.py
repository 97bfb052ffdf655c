#!/usr/bin/python3
"""Memory per rank as ranks grow (issue 11, part 4): the Q2 cantilever of cantilever.prm on
n x n x 10n hexahedra (n = 16: 1.05M DoFs), matrix-free solve, on 1, 2 and 4 ranks
(oversubscribed on a 2-core machine: memory is what is measured, not time), with the mesh shared
(every rank holds all of it) and distributed (each rank holds its METIS part; rank 0 reads and
cuts it). Prints and writes memory_per_rank.{md,csv}: peak resident memory (VmHWM) of the largest
and the smallest rank and of all ranks together, wall time, tip deflection.

  /usr/bin/python3 cases/benchmarks/memory_per_rank.py [--n 16] [--ranks 1,2,4]"""
import argparse
import csv
import json
import os
import shutil
import subprocess
import tempfile
import time

from report_header import provenance

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SOLVER = os.environ.get("COMPLIANT_SOLVER", os.path.join(ROOT, "build", "solver", "fe", "compliant"))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def run(n, ranks, partition):
    out = tempfile.mkdtemp(prefix="memory-")
    cmd = ["mpirun", "-np", str(ranks), SOLVER, os.path.join(HERE, "cantilever.prm"),
           "--set", "Output/Directory=" + out, "--set", "Geometry/Parameters/ny=%d" % n,
           "--set", "Geometry/Parameters/nz=%d" % n,
           "--set", "Discretization/Mesh partition=" + partition]
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        shutil.rmtree(out, ignore_errors=True)
        raise RuntimeError(" ".join(cmd) + "\n" + proc.stderr[-2000:])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    shutil.rmtree(out, ignore_errors=True)
    q = summary["quantities"]
    return {"n": n, "ranks": ranks, "partition": summary["settings"]["mesh_partition"],
            "dofs": int(q["n_dofs"]), "max_rank_mb": q["memory_peak_max_rank_mb"],
            "min_rank_mb": q["memory_peak_min_rank_mb"], "all_ranks_mb": q["memory_peak_all_ranks_mb"],
            "wall_s": wall, "solve_s": q["time_solve"], "iterations": int(q["solver_iterations"]),
            "tip": -q["displacement_tip_z"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--n", type=int, default=16)
    parser.add_argument("--ranks", default="1,2,4")
    parser.add_argument("--out", default=HERE)
    args = parser.parse_args()
    # What every process holds whatever the model: the libraries' resident pages, MPI, PETSc.
    base = run(1, 1, "shared")["max_rank_mb"]
    print("fixed footprint of one process (n = 1, 78 DoFs): %.0f MB" % base, flush=True)
    rows = []
    for ranks in [int(r) for r in args.ranks.split(",")]:
        for partition in ("shared", "distributed") if ranks > 1 else ("shared",):
            row = run(args.n, ranks, partition)
            rows.append(row)
            print("%d ranks, %-11s: max rank %.0f MB, min rank %.0f MB, all ranks %.0f MB, wall %.1f s, "
                  "tip %.9f" % (ranks, row["partition"], row["max_rank_mb"], row["min_rank_mb"],
                                row["all_ranks_mb"], row["wall_s"], row["tip"]), flush=True)
    with open(os.path.join(args.out, "memory_per_rank.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# Memory per rank", ""] + provenance() + ["Q2 cantilever n = %d (%d DoFs), matrix-free p-multigrid; peak resident memory (VmHWM) per "
             "rank. Ranks beyond 2 are oversubscribed on this 2-core machine: times there are not "
             "speeds." % (args.n, rows[0]["dofs"]), "",
             "The fixed footprint of one process (libraries, MPI, PETSc; measured on an n = 1 "
             "model) is %.0f MB; the last column is the largest rank less that footprint, against "
             "the 1-rank figure less it divided by the ranks." % base, "",
             "| ranks | mesh | largest rank (MB) | smallest rank (MB) | all ranks (MB) | model part of largest rank (MB) | ideal share (MB) | wall (s) | solve (s) | CG its | tip deflection |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    one_rank = rows[0]["max_rank_mb"] - base
    for r in rows:
        lines.append("| %d | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.1f | %.1f | %d | %.9f |" % (
            r["ranks"], r["partition"], r["max_rank_mb"], r["min_rank_mb"], r["all_ranks_mb"],
            r["max_rank_mb"] - base, one_rank / r["ranks"], r["wall_s"], r["solve_s"], r["iterations"],
            r["tip"]))
    with open(os.path.join(args.out, "memory_per_rank.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
