#!/usr/bin/python3
"""Newton steps of a 3D finite-strain flexure: MUMPS on the assembled tangent against CG with the
p-multigrid on the matrix-free tangent (issue 11, part 3). The case is
cases/benchmarks/flexure_finite_strain.prm (TPU strip 20 x 5 x 1 mm, end turned 45 degrees, Q2,
neo-Hookean) on a mesh ladder; both methods run one after the other per mesh on 2 ranks.

For each run: DoFs, Newton iterations, CG iterations per Newton step, time per Newton step
(tangent or residual assembly plus linear solve, over the Newton iterations), whole-process wall
time, peak memory of the largest rank, and the answer (reaction moment at the turned end, the
mid-point deflection) with its relative difference from the MUMPS run on the same mesh.

  /usr/bin/python3 cases/benchmarks/finite_strain_speed.py [--meshes 40x8x2,60x12x3,80x16x3]
      [--methods direct,matrix-free]

Writes cases/benchmarks/finite_strain_speed.{csv,md,png}."""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

from report_header import fit_slope, provenance

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SOLVER = os.environ.get("COMPLIANT_SOLVER", os.path.join(ROOT, "build", "solver", "fe", "compliant"))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
QOIS = ("reaction_moment_right_y", "displacement_mid_z")


def run(mesh, method, ranks):
    nx, ny, nz = mesh
    out = tempfile.mkdtemp(prefix="fs-bench-")
    cmd = ["mpirun", "-np", str(ranks), SOLVER, os.path.join(HERE, "flexure_finite_strain.prm"),
           "--set", "Linear solver/Method=" + method, "--set", "Output/Directory=" + out,
           "--set", "Geometry/Parameters/nx=%d" % nx, "--set", "Geometry/Parameters/ny=%d" % ny,
           "--set", "Geometry/Parameters/nz=%d" % nz]
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit("run failed (%s):\n%s\n%s" % (" ".join(cmd), proc.stdout[-2000:], proc.stderr[-2000:]))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    q = summary["quantities"]
    newton = q["newton_iterations"]
    row = dict(mesh="%dx%dx%d" % mesh, method=method, solver=summary["settings"]["solver"],
               dofs=int(q["n_dofs"]), newton=int(newton),
               cg_per_step=q.get("linear_iterations", 0) / max(q["linear_solves"], 1),
               assembly=q["time_tangent_assembly"], solves=q["time_linear_solves"],
               per_step=(q["time_tangent_assembly"] + q["time_linear_solves"]) / newton,
               wall=wall, memory=q.get("memory_peak_max_rank_mb", float("nan")))
    for name in QOIS:
        row[name] = q[name]
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--meshes", default="40x8x2,60x12x3,80x16x3")
    parser.add_argument("--methods", default="direct,matrix-free")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--output", default=os.path.join(HERE, "finite_strain_speed"))
    args = parser.parse_args()
    meshes = [tuple(int(v) for v in m.split("x")) for m in args.meshes.split(",")]
    rows = []
    for mesh in meshes:
        for method in args.methods.split(","):
            row = run(mesh, method, args.ranks)
            rows.append(row)
            print("%s %-12s %7d DoFs: %2d Newton, %.1f s per step, wall %.1f s, M = %.10g" %
                  (row["mesh"], method, row["dofs"], row["newton"], row["per_step"], row["wall"],
                   row[QOIS[0]]), flush=True)
    # Differences against the MUMPS answer on the same mesh.
    for row in rows:
        base = next((r for r in rows if r["mesh"] == row["mesh"] and r["method"] == "direct"), None)
        for name in QOIS:
            row[name + "_difference"] = (abs(row[name] - base[name]) / abs(base[name])) if base else float("nan")

    with open(args.output + ".csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    lines = ["# Finite-strain Newton steps: MUMPS against the matrix-free p-multigrid",
             ""] + provenance() + [
             "Case `cases/benchmarks/flexure_finite_strain.prm`, %d ranks. Time per Newton step = "
             "(tangent or residual assembly + linear solve) / Newton iterations; the difference is "
             "relative to the MUMPS run on the same mesh." % args.ranks,
             "",
             "| mesh | DoFs | method | Newton its | CG its per step | assembly (s) | solves (s) | "
             "per Newton step (s) | whole process (s) | peak MB/rank | moment M_y | difference | "
             "mid deflection | difference |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        lines.append("| %s | %d | %s | %d | %.1f | %.1f | %.1f | %.2f | %.1f | %.0f | %.10g | %.1e | %.10g | %.1e |" % (
            r["mesh"], r["dofs"], r["method"], r["newton"], r["cg_per_step"], r["assembly"],
            r["solves"], r["per_step"], r["wall"], r["memory"], r[QOIS[0]],
            r[QOIS[0] + "_difference"], r[QOIS[1]], r[QOIS[1] + "_difference"]))
    lines.append("")
    for mesh in dict.fromkeys(r["mesh"] for r in rows):
        d = next((r for r in rows if r["mesh"] == mesh and r["method"] == "direct"), None)
        m = next((r for r in rows if r["mesh"] == mesh and r["method"] == "matrix-free"), None)
        if d and m:
            lines.append("- %s (%d DoFs): per Newton step %.2f s (MUMPS) against %.2f s (matrix-free), "
                         "%.1f times faster; whole process %.1f against %.1f s" %
                         (mesh, d["dofs"], d["per_step"], m["per_step"], d["per_step"] / m["per_step"],
                          d["wall"], m["wall"]))
    lines += ["", "Time per Newton step against DoFs (least-squares slope over the meshes):", ""]
    for method in dict.fromkeys(r["method"] for r in rows):
        points = [(r["dofs"], r["per_step"]) for r in rows if r["method"] == method]
        lines.append("- %s: slope %.2f over %d meshes" % (method, fit_slope(points), len(points)))
    lines += ["", "![time per Newton step](%s.png)" % os.path.basename(args.output)]
    with open(args.output + ".md", "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    chart(rows, args.output + ".png", args.ranks)


def chart(rows, path, ranks):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    for method in dict.fromkeys(r["method"] for r in rows):
        rs = sorted((r for r in rows if r["method"] == method), key=lambda r: r["dofs"])
        ax.loglog([r["dofs"] for r in rs], [r["per_step"] for r in rs], "o-", label=method)
    ax.set_xlabel("DoFs")
    ax.set_ylabel("time per Newton step (s), %d ranks" % ranks)
    ax.set_title("flexure_finite_strain.prm: neo-Hookean strip turned 45 degrees")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)


if __name__ == "__main__":
    main()
