#!/usr/bin/python3
"""Speed against accuracy, this solver against FEniCSx and CalculiX on the same machine in the same
run (issue 11). The cantilever of cases/benchmarks/cantilever.prm on n x n x 10n hexahedra: ours
(Q2; each linear-solver method), FEniCSx (Q2 Lagrange, CG + GAMG with block size and rigid-body
modes), CalculiX (C3D20R, SPOOLES, 2 threads). For each mesh the codes run one after another, so
they share the machine's load. Wall time is the whole process as a user sees it (mpirun to exit).

The reference tip deflection is extrapolated from our three finest Q2 meshes (Richardson with the
observed order); every code's error is against it.

  scripts/setup.sh peers        # once: installs calculix-ccx and python3-dolfinx, builds
  /usr/bin/python3 cases/benchmarks/speed_vs_peers.py [--problem cantilever|leaf|hinge|flexure-finite-strain] [--n ...] [--methods auto,cg-amg,direct]

Writes cases/benchmarks/<problem>_speed.{csv,md,png}. --problem leaf: the thin leaf in torsion of
cases/benchmarks/leaf_torsion.prm (strain energy as QoI). --problem hinge: the 3D blade flexure hinge of
cases/benchmarks/hinge_3d.prm on the structured mesh of peers/hinge_mesh.py, written per level for
all three codes (strain energy as QoI)."""
import argparse
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

from report_header import fit_slope, provenance

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
SOLVER = os.environ.get("COMPLIANT_SOLVER", os.path.join(ROOT, "build", "solver", "fe", "compliant"))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


# Each problem: our case file, the mesh parameters for ladder value n, how to read our QoI, the
# FEniCSx script, the Q2 DoF count (to skip expensive methods), and the QoI's name.
PROBLEMS = {
    "cantilever": dict(case="cantilever.prm", mesh=lambda n: {"ny": n, "nz": n},
                       qoi=lambda q: -q["displacement_tip_z"], fenicsx="fenicsx_cantilever.py",
                       fenicsx_qoi=lambda v: -v, calculix_qoi=lambda v: -v,
                       dofs=lambda n: 3 * (2 * n + 1) ** 2 * (20 * n + 1),
                       label="tip deflection", title="3D cantilever, n x n x 10n hexahedra"),
    "leaf": dict(case="leaf_torsion.prm", mesh=lambda n: {"nx": 5 * n, "ny": 10 * n, "nz": n},
                 qoi=lambda q: q["strain_energy"], fenicsx="fenicsx_leaf.py", fenicsx_qoi=lambda v: v,
                 calculix_qoi=lambda v: v,
                 dofs=lambda n: 3 * (10 * n + 1) * (20 * n + 1) * (2 * n + 1),
                 label="strain energy", title="leaf in torsion, 5m x 10m x m hexahedra (cells 8:1:1)"),
}
sys.path.insert(0, os.path.join(HERE, "peers"))
import hinge_mesh  # noqa: E402

PROBLEMS["hinge"] = dict(case="hinge_3d.prm", mesh=lambda m: {}, mesh_file=hinge_mesh.write_inp,
                         qoi=lambda q: q["strain_energy"], fenicsx="fenicsx_hinge.py", fenicsx_qoi=lambda v: v,
                         calculix_qoi=lambda v: v, dofs=hinge_mesh.q2_dofs, label="strain energy",
                         title="3D blade flexure hinge, level m (blade cells 4:1:5)")
# Finite strain (issue 30, item 2): the neo-Hookean strip turned 45 degrees of flexure_finite_strain.prm
# on 20n x 4n x n cells; FEniCSx with the same law, quadrature and load factors; CalculiX NLGEOM with
# C3D20R and its NEO HOOKE law (the same small-strain mu and K, isochoric I1bar and (J - 1)^2 at finite
# strain), the end on a *RIGID BODY turned 45 degrees, 6 increments (peers/calculix_flexure_finite_strain.py).
PROBLEMS["flexure-finite-strain"] = dict(
    case="flexure_finite_strain.prm", mesh=lambda n: {"nx": 20 * n, "ny": 4 * n, "nz": n},
    qoi=lambda q: q["reaction_moment_right_y"], fenicsx="fenicsx_flexure_finite_strain.py",
    fenicsx_qoi=lambda v: v, fenicsx_args=["direct"], fenicsx_variant="mumps", peers=["fenicsx", "calculix"],
    calculix="calculix_flexure_finite_strain.py", calculix_args=lambda n, work: [str(n), work],
    calculix_qoi=lambda v: v, calculix_variant="C3D20R spooles", solve_key="time_linear_solves",
    iterations_key="newton_iterations", dofs=lambda n: 3 * (40 * n + 1) * (8 * n + 1) * (2 * n + 1),
    label="end moment M_y", title="TPU strip turned 45 degrees (neo-Hookean, 6 load steps), 20n x 4n x n hexahedra")
PROBLEM = PROBLEMS["cantilever"]


def run_ours(n, method, ranks):
    work = tempfile.mkdtemp(prefix="bench-")
    out = os.path.join(work, "run")
    cmd = ["mpirun", "-np", str(ranks), SOLVER, os.path.join(HERE, PROBLEM["case"]),
           "--set", "Linear solver/Method=" + method, "--set", "Output/Directory=" + out]
    for name, value in PROBLEM["mesh"](n).items():
        cmd += ["--set", "Geometry/Parameters/%s=%d" % (name, value)]
    if "mesh_file" in PROBLEM:  # the mesh the peers solve, written for this level
        PROBLEM["mesh_file"](n, os.path.join(work, "mesh.inp"))
        cmd += ["--set", "Geometry/Mesh file=" + os.path.join(work, "mesh.inp")]
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        shutil.rmtree(work, ignore_errors=True)
        return {"skipped": proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else "failed"}
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    shutil.rmtree(work, ignore_errors=True)
    q = summary["quantities"]
    return {"dofs": q["n_dofs"], "qoi": PROBLEM["qoi"](q), "wall_s": wall,
            "solve_s": q[PROBLEM.get("solve_key", "time_solve")],
            "iterations": q[PROBLEM.get("iterations_key", "solver_iterations")],
            "memory_mb": q.get("memory_peak_max_rank_mb", float("nan")),
            "method": summary["settings"].get("solver", method)}


def run_fenicsx(n, ranks):
    cmd = ["mpirun", "-np", str(ranks), "/usr/bin/python3", os.path.join(HERE, "peers", PROBLEM["fenicsx"]), str(n)] + \
        PROBLEM.get("fenicsx_args", [])
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=ENV)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        return {"skipped": "FEniCSx failed: " + proc.stderr.strip()[-300:]}
    r = json.loads([l for l in proc.stdout.splitlines() if l.startswith("{")][-1])
    return {"dofs": r["dofs"], "qoi": PROBLEM["fenicsx_qoi"](r["qoi"]), "wall_s": wall, "solve_s": r["solve_s"],
            "iterations": r["iterations"], "memory_mb": r["memory_mb"]}


def run_calculix(n):
    """One CalculiX run by the problem's helper (calculix_box.py PROBLEM N WORK by default)."""
    work = tempfile.mkdtemp(prefix="ccx-")
    script = os.path.join(HERE, "peers", PROBLEM.get("calculix", "calculix_box.py"))
    args = PROBLEM.get("calculix_args", lambda n, work: [PROBLEM_NAME, str(n), work])(n, work)
    proc = subprocess.run(["/usr/bin/python3", script] + args, capture_output=True, text=True)
    shutil.rmtree(work, ignore_errors=True)
    if proc.returncode != 0:
        return {"skipped": "CalculiX failed: " + proc.stderr.strip()[-300:]}
    r = json.loads(proc.stdout.strip().splitlines()[-1])
    # ccx does not report its solve separately; its wall time is the whole process. Linear
    # problems: one solve; nonlinear ones: the helper's Newton iterations.
    out = {"dofs": r["dofs"], "qoi": PROBLEM["calculix_qoi"](r["qoi"]), "wall_s": r["wall_s"], "solve_s": float("nan"),
           "iterations": r.get("iterations", 1), "memory_mb": r["memory_mb"]}
    out.update({k: r[k] for k in ("increments", "factors") if k in r})  # printed, not tabled
    return out


def richardson(ns, qs):
    """(observed order p, extrapolated limit) of q(n) = q_inf + C n^-p through three meshes n0 < n1 < n2
    (cells across ~ n). Any three meshes, not only a halving ladder: with n = 1, 2, 3 the spacing
    ratio is 2 then 1.5, and one ratio for both misplaces the limit. p by bisection on the ratio of
    the two differences, (n0^-p - n1^-p) / (n1^-p - n2^-p), which grows with p."""
    (n0, n1, n2), (q0, q1, q2) = ns, qs
    if q2 == q1:
        return float("nan"), q2
    target = abs((q0 - q1) / (q1 - q2))
    ratio = lambda p: (n0 ** -p - n1 ** -p) / (n1 ** -p - n2 ** -p)  # noqa: E731
    lo, hi = 1e-3, 20.0
    if not ratio(lo) < target < ratio(hi):
        return float("nan"), q2
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if ratio(mid) < target else (lo, mid)
    p = 0.5 * (lo + hi)
    return p, q2 - (q1 - q2) / (n1 ** -p - n2 ** -p) * n2 ** -p


def time_at_error(rows, target):
    """Wall time at a given error, interpolated log-log between the two bracketing meshes."""
    pts = sorted((r["error"], r["wall_s"]) for r in rows if r["error"] > 0)
    for (e0, t0), (e1, t1) in zip(pts, pts[1:]):
        if e0 <= target <= e1:
            w = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t1) - math.log(t0)))
    return float("nan")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--problem", default="cantilever", choices=sorted(PROBLEMS))
    parser.add_argument("--n", default=None, help="mesh ladder (cantilever: cells across, default 2,4,6,8,12,16; "
                        "leaf: cells through the thickness, default 1,2,3,4,6,8)")
    parser.add_argument("--methods", default="auto,cg-amg,direct", help="our Linear solver/Method values")
    parser.add_argument("--peers", default="fenicsx,calculix")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--direct-max-dofs", type=float, default=1.5e5, help="MUMPS grows fast: skip above")
    parser.add_argument("--amg-max-dofs", type=float, default=5e5)
    parser.add_argument("--peer-max-n", type=int, default=12)
    parser.add_argument("--out", default=HERE)
    args = parser.parse_args()
    global PROBLEM, PROBLEM_NAME
    PROBLEM, PROBLEM_NAME = PROBLEMS[args.problem], args.problem
    args.n = args.n or {"cantilever": "2,4,6,8,12,16", "leaf": "1,2,3,4,6", "hinge": "2,3,4,6,8,10",
                        "flexure-finite-strain": "1,2,3,4,5"}[args.problem]
    ladder = [int(v) for v in args.n.split(",")]
    methods = [m for m in args.methods.split(",") if m]
    peers = [p for p in args.peers.split(",") if p and p in PROBLEM.get("peers", ["fenicsx", "calculix"])]
    if args.problem == "cantilever" and "calculix" in peers and any(n % 2 for n in ladder):
        sys.exit("speed_vs_peers.py: --n %s: the cantilever's tip (the end face's centre) is a node of "
                 "CalculiX's 20-node mesh for even n only" % args.n)
    if "fenicsx" in peers:  # warm FEniCSx's JIT cache so no run pays for compiling forms
        run_fenicsx(1, 1)
    rows = []
    for n in ladder:
        dofs_q2 = PROBLEM["dofs"](n)
        for m in methods:
            cap = {"direct": args.direct_max_dofs, "cg-amg": args.amg_max_dofs}.get(m, float("inf"))
            if dofs_q2 > cap:
                continue
            r = run_ours(n, m, args.ranks)
            r.update(code="compliant", variant=m, n=n)
            rows.append(r)
            print(json.dumps(r), flush=True)
        if n <= args.peer_max_n:
            for peer in peers:
                r = run_fenicsx(n, args.ranks) if peer == "fenicsx" else run_calculix(n)
                variant = PROBLEM.get("fenicsx_variant", "gamg") if peer == "fenicsx" else PROBLEM.get("calculix_variant", "spooles")
                r.update(code=peer, variant=variant, n=n)
                rows.append(r)
                print(json.dumps(r), flush=True)
    done = [r for r in rows if "skipped" not in r]
    ours = sorted({r["n"]: r for r in done if r["code"] == "compliant"}.values(), key=lambda r: r["n"])
    # Richardson on the three finest meshes of a halving ladder (n, 2n, 4n) if present, else the finest three.
    q = {r["n"]: r["qoi"] for r in ours}
    triple = next(((a, 2 * a, 4 * a) for a in sorted(q, reverse=True) if 4 * a in q and 2 * a in q), None)
    if triple is None:
        ns = sorted(q)[-3:]
        triple = tuple(ns)
    order, reference = richardson(triple, [q[t] for t in triple])
    for r in done:
        r["error"] = abs(r["qoi"] - reference) / abs(reference)
    print("\nReference %s %.9g (Richardson on our n = %s, observed order %.2f)" % (PROBLEM["label"], reference, triple, order))

    os.makedirs(args.out, exist_ok=True)
    keys = ["code", "variant", "n", "dofs", "qoi", "error", "wall_s", "solve_s", "iterations", "memory_mb"]
    with open(os.path.join(args.out, "%s_speed.csv" % PROBLEM_NAME), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys + ["method", "skipped"], extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    lines = ["| code | method | n | DoFs | %s | error | wall (s) | solve (s) | iterations | peak MB/rank |" % PROBLEM["label"],
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in done:
        lines.append("| %s | %s | %d | %d | %.7g | %.1e | %.2f | %s | %d | %.0f |" % (
            r["code"], r["variant"], r["n"], r["dofs"], r["qoi"], r["error"], r["wall_s"],
            "-" if math.isnan(r["solve_s"]) else "%.2f" % r["solve_s"], r["iterations"], r["memory_mb"]))
    groups = {}
    for r in done:
        groups.setdefault((r["code"], r["variant"]), []).append(r)
    lines += ["", "Solve time against DoFs (least-squares slope from 1.5e4 DoFs up):", ""]
    for (code, variant), rs in groups.items():
        pts = [(r["dofs"], r["solve_s"] if not math.isnan(r["solve_s"]) else r["wall_s"]) for r in rs if r["dofs"] >= 1.5e4]
        lines.append("- %s %s: slope %.2f over %d meshes%s" % (code, variant, fit_slope(pts), len(pts),
                                                               " (whole process)" if code == "calculix" else ""))
    ours_fast = groups.get(("compliant", "auto")) or groups.get(("compliant", methods[0]), [])
    lines += ["", "Wall time at equal accuracy (log-log interpolation between meshes), peer / ours (%s):" % (
        ours_fast[0]["variant"] if ours_fast else "-"), ""]
    # At the error of each of our meshes (peers interpolated there; nan outside their range).
    for target in sorted({r["error"] for r in ours_fast if r["error"] > 0}, reverse=True):
        ours_t = time_at_error(ours_fast, target)
        if math.isnan(ours_t):
            ours_t = min(r["wall_s"] for r in ours_fast if r["error"] == target)
        cells = []
        for (code, variant), rs in groups.items():
            if code == "compliant":
                continue
            cells.append("%s %.1f" % (code, time_at_error(rs, target) / ours_t))
        lines.append("- error %.1e: ours %.2f s; %s" % (target, ours_t, ", ".join(cells)))
    skipped = [r for r in rows if "skipped" in r]
    for r in skipped:
        lines.append("- skipped %s %s n=%d: %s" % (r["code"], r["variant"], r["n"], r["skipped"]))
    text = "\n".join(lines)
    with open(os.path.join(args.out, "%s_speed.md" % PROBLEM_NAME), "w") as f:
        f.write("\n".join(["# Speed against accuracy: %s" % PROBLEM["title"], ""] + provenance()) + "\n" +
                "Reference %s %.9g (Richardson on our n = %s, observed order %.2f); "
                "%d ranks.\n\n" % (PROBLEM["label"], reference, triple, order, args.ranks) + text + "\n")
    print(text)

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    for (code, variant), rs in groups.items():
        rs = sorted(rs, key=lambda r: r["dofs"])
        ax.loglog([r["wall_s"] for r in rs], [r["error"] for r in rs], "o-" if code == "compliant" else "s--",
                  label="%s, %s" % (code, variant))
    ax.set_xlabel("wall time, whole process (s), %d ranks" % args.ranks)
    ax.set_ylabel("relative error of the %s" % PROBLEM["label"])
    ax.set_title("%s, n = %s" % (PROBLEM["title"], args.n))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(args.out, "%s_speed.png" % PROBLEM_NAME), dpi=120)


if __name__ == "__main__":
    sys.exit(main())
