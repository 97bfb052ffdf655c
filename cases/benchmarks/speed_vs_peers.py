#!/usr/bin/python3
"""Speed against accuracy, this solver against FEniCSx and CalculiX on the same machine in the same
run (issue 11). The cantilever of cases/benchmarks/cantilever.prm on n x n x 10n hexahedra: ours
(Q2; each linear-solver method), FEniCSx (Q2 Lagrange, CG + GAMG with block size and rigid-body
modes), CalculiX (C3D20R, SPOOLES, 2 threads). For each mesh the codes run one after another, so
they share the machine's load. Wall time is the whole process as a user sees it (mpirun to exit).

The reference QoI is extrapolated from our three finest meshes (Richardson with the observed order)
at the highest --degree, or given by --reference; every code's and degree's error is against the same
value. --degree 2,3,4 runs our ladder at each element degree (--set "Discretization/Element degree=K";
the DoF estimate that skips the assembled methods scales with K); --max-wall stops one of our ladders
after a run longer than that; --targets 0.01,0.003,0.001 adds the wall time at which each ladder
reaches those errors and its ratio to each peer; --name writes <name>_speed.* instead of <problem>_speed.*;
--integration full,reduced runs ours with each Discretization/Integration; --grade 1,50 runs every ladder (ours and CalculiX's) also on meshes graded along x, the longest cell 50
times the shortest (meshes/graded_layers.geo; toward the clamp of the cantilever, both ends of the leaf
and the strip; the hinge's every x segment toward both its ends and the blocks' y segments toward the
blade, peers/hinge_mesh.py).

  scripts/setup.sh peers        # once: installs calculix-ccx and python3-dolfinx, builds
  /usr/bin/python3 cases/benchmarks/speed_vs_peers.py [--problem cantilever|leaf|hinge|flexure-finite-strain] [--n ...] [--methods auto,cg-amg,direct]
      [--degree 2[,3,4]] [--grade 1[,G]] [--reference VALUE --reference-note TEXT] [--max-wall S] [--targets E,...]
      [--name NAME]

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
# FEniCSx script, our DoF count at ladder value n and element degree k (to skip expensive methods),
# the QoI's name, and where a graded mesh puts its shortest cells (graded_ends of
# meshes/graded_layers.geo; absent: no graded meshes).
PROBLEMS = {
    "cantilever": dict(case="cantilever.prm", mesh=lambda n: {"ny": n, "nz": n},
                       qoi=lambda q: -q["displacement_tip_z"], fenicsx="fenicsx_cantilever.py",
                       fenicsx_qoi=lambda v: -v, calculix_qoi=lambda v: -v,
                       dofs=lambda n, k=2: 3 * (k * n + 1) ** 2 * (10 * k * n + 1),
                       label="tip deflection", title="3D cantilever, n x n x 10n hexahedra", graded_ends=1),
    "leaf": dict(case="leaf_torsion.prm", mesh=lambda n: {"nx": 5 * n, "ny": 10 * n, "nz": n},
                 qoi=lambda q: q["strain_energy"], fenicsx="fenicsx_leaf.py", fenicsx_qoi=lambda v: v,
                 calculix_qoi=lambda v: v,
                 dofs=lambda n, k=2: 3 * (5 * k * n + 1) * (10 * k * n + 1) * (k * n + 1),
                 label="strain energy", title="leaf in torsion, 5m x 10m x m hexahedra (cells 8:1:1)",
                 graded_ends=0),
}
sys.path.insert(0, os.path.join(HERE, "peers"))
import hinge_mesh  # noqa: E402

PROBLEMS["hinge"] = dict(case="hinge_3d.prm", mesh=lambda m: {}, mesh_file=hinge_mesh.write_inp, graded_ends="roots",
                         qoi=lambda q: q["strain_energy"], fenicsx="fenicsx_hinge.py", fenicsx_qoi=lambda v: v,
                         calculix_qoi=lambda v: v, dofs=lambda m, k=2: hinge_mesh.q2_dofs(m) * (k / 2) ** 3,
                         label="strain energy",
                         title="3D blade flexure hinge, level m (blade cells 4:1:5)")
# Finite strain (issue 30, item 2): the neo-Hookean strip turned 45 degrees of flexure_finite_strain.prm
# on 20n x 4n x n cells; FEniCSx with the same law, quadrature and load factors; CalculiX NLGEOM with
# C3D20R and its NEO HOOKE law (the same small-strain mu and K, isochoric I1bar and (J - 1)^2 at finite
# strain), the end on a *RIGID BODY turned 45 degrees, 6 increments (peers/calculix_flexure_finite_strain.py).
PROBLEMS["flexure-finite-strain"] = dict(
    case="flexure_finite_strain.prm", mesh=lambda n: {"nx": 20 * n, "ny": 4 * n, "nz": n},
    qoi=lambda q: q["reaction_moment_right_y"], fenicsx="fenicsx_flexure_finite_strain.py",
    fenicsx_qoi=lambda v: v, fenicsx_args=["direct"], fenicsx_variant="mumps", peers=["fenicsx", "calculix"],
    calculix="calculix_flexure_finite_strain.py", calculix_args=lambda n, work, grade: [str(n), work, "--grade", repr(grade)],
    calculix_qoi=lambda v: v, calculix_variant="C3D20R spooles", solve_key="time_linear_solves",
    iterations_key="newton_iterations", graded_ends=0,
    dofs=lambda n, k=2: 3 * (20 * k * n + 1) * (4 * k * n + 1) * (k * n + 1),
    label="end moment M_y", title="TPU strip turned 45 degrees (neo-Hookean, 6 load steps), 20n x 4n x n hexahedra")
PROBLEM = PROBLEMS["cantilever"]


def graded_mesh(grade):
    """Our mesh parameters for a mesh graded along x ({} for a uniform one, or one written by the
    problem's mesh_file, which grades it itself)."""
    if grade == 1 or "mesh_file" in PROBLEM:  # parse_arguments refused problems without graded meshes
        return {}
    return {"grade_x": grade, "graded_ends": PROBLEM["graded_ends"]}


def run_ours(n, method, ranks, degree=2, grade=1, integration="full"):
    work = tempfile.mkdtemp(prefix="bench-")
    out = os.path.join(work, "run")
    cmd = ["mpirun", "-np", str(ranks), SOLVER, os.path.join(HERE, PROBLEM["case"]),
           "--set", "Linear solver/Method=" + method, "--set", "Output/Directory=" + out,
           "--set", "Discretization/Element degree=%d" % degree, "--set", "Discretization/Integration=" + integration]
    for name, value in dict(PROBLEM["mesh"](n), **graded_mesh(grade)).items():
        cmd += ["--set", "Geometry/Parameters/%s=%s" % (name, value)]
    if "mesh_file" in PROBLEM:  # the mesh the peers solve, written for this level
        PROBLEM["mesh_file"](n, os.path.join(work, "mesh.inp"), grade)
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


def run_fenicsx(n, ranks, grade=1):
    if grade != 1:
        return {"skipped": "the FEniCSx scripts mesh uniformly"}
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


def run_calculix(n, grade=1):
    """One CalculiX run by the problem's helper (calculix_box.py PROBLEM N WORK [GRADE] by default)."""
    work = tempfile.mkdtemp(prefix="ccx-")
    script = os.path.join(HERE, "peers", PROBLEM.get("calculix", "calculix_box.py"))
    args = PROBLEM.get("calculix_args", lambda n, work, grade: [PROBLEM_NAME, str(n), work, repr(grade)])(n, work, grade)
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


def time_to_reach(rows, target):
    """(wall time, note) at which a mesh ladder first reaches an error: walking the meshes from coarse
    to fine, log-log interpolation between the last mesh above the target and the first at or below
    it. Unlike time_at_error, an error that is not monotone (a code converging to a slightly different
    value, or crossing the reference) is not paired across meshes. note: "" interpolated, "<=" the
    coarsest mesh is already there (its time is an upper bound), "not reached" nan."""
    pts = [(r["error"], r["wall_s"]) for r in sorted(rows, key=lambda r: r["dofs"])]
    if not pts:
        return float("nan"), "not reached"
    if pts[0][0] <= target:
        return pts[0][1], "<="
    for (e0, t0), (e1, t1) in zip(pts, pts[1:]):
        if e1 <= target < e0:
            if e1 <= 0:
                return t1, "<="
            w = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + w * (math.log(t1) - math.log(t0))), ""
    return float("nan"), "not reached"


def reference_from(rows, finest=False):
    """(order, limit, meshes) by Richardson on one ladder of our runs: the three finest of a halving
    ladder (n, 2n, 4n) if present, else (or with finest) the finest three."""
    q = {r["n"]: r["qoi"] for r in rows}
    if len(q) < 3:
        return float("nan"), (max(q.items())[1] if q else float("nan")), tuple(sorted(q))
    triple = None if finest else next(((a, 2 * a, 4 * a) for a in sorted(q, reverse=True)
                                       if 4 * a in q and 2 * a in q), None)
    if triple is None:
        triple = tuple(sorted(q)[-3:])
    order, limit = richardson(triple, [q[t] for t in triple])
    return order, limit, triple


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--problem", default="cantilever", choices=sorted(PROBLEMS))
    parser.add_argument("--n", default=None, help="mesh ladder (cantilever: cells across, default 2,4,6,8,12,16; "
                        "leaf: cells through the thickness, default 1,2,3,4,6,8)")
    parser.add_argument("--methods", default="auto,cg-amg,direct", help="our Linear solver/Method values")
    parser.add_argument("--degree", default="2", help="our element degree(s), comma-separated (e.g. 2,3,4): "
                        "each is run on the ladder as --set 'Discretization/Element degree=K'; with more than "
                        "one, or one other than 2, the method column reads e.g. 'auto Q3'")
    parser.add_argument("--grade", default="1", help="mesh grading(s) along x, comma-separated: the longest "
                        "cell over the shortest (1 uniform); each is run on every ladder, ours and the peers' "
                        "where they can mesh it, the method column then reads e.g. 'auto, graded 50'")
    parser.add_argument("--integration", default="full", help="our Discretization/Integration value(s), "
                        "comma-separated (full, reduced): each is run on every ladder of ours, the method "
                        "column then reads e.g. 'auto, reduced'")
    parser.add_argument("--reference", type=float, default=None,
                        help="the reference QoI every error is measured against; default: Richardson on our "
                        "three finest meshes at the highest degree (first method, first grade), the same for all")
    parser.add_argument("--reference-note", default="", help="how --reference was obtained (for the report)")
    parser.add_argument("--max-wall", type=float, default=float("inf"),
                        help="stop one of our (method, degree, grade) ladders after a run longer than this (s)")
    parser.add_argument("--targets", default="", help="errors (e.g. 0.01,0.003,0.001) at which to report every "
                        "ladder's wall time and the ratio to each peer")
    parser.add_argument("--name", default=None, help="report name: writes <name>_speed.{csv,md,png} "
                        "(default: the problem's name)")
    parser.add_argument("--peers", default="fenicsx,calculix")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--direct-max-dofs", type=float, default=1.5e5, help="MUMPS grows fast: skip above")
    parser.add_argument("--amg-max-dofs", type=float, default=5e5)
    parser.add_argument("--peer-max-n", type=int, default=12)
    parser.add_argument("--out", default=HERE)
    args = parser.parse_args()
    args.n = args.n or {"cantilever": "2,4,6,8,12,16", "leaf": "1,2,3,4,6", "hinge": "2,3,4,6,8,10",
                        "flexure-finite-strain": "1,2,3,4,5"}[args.problem]
    args.ladder = [int(v) for v in args.n.split(",")]
    args.method_list = [m for m in args.methods.split(",") if m]
    args.degrees = [int(v) for v in args.degree.split(",") if v]
    args.grades = [float(v) for v in args.grade.split(",") if v]
    args.integrations = [v for v in args.integration.split(",") if v]
    args.peer_list = [p for p in args.peers.split(",") if p and p in PROBLEMS[args.problem].get("peers", ["fenicsx", "calculix"])]
    if any(g < 1 for g in args.grades) or (args.grades != [1] and "graded_ends" not in PROBLEMS[args.problem]):
        sys.exit("speed_vs_peers.py: --grade %s: gradings >= 1, and only for problems with graded meshes (%s)" % (
            args.grade, ", ".join(k for k, v in PROBLEMS.items() if "graded_ends" in v)))
    if args.problem == "cantilever" and "calculix" in args.peer_list and any(n % 2 for n in args.ladder):
        sys.exit("speed_vs_peers.py: --n %s: the cantilever's tip (the end face's centre) is a node of "
                 "CalculiX's 20-node mesh for even n only" % args.n)
    return args


def variant_label(base, degree, grade, args, integration="full"):
    """The method column: the method or solver, then the degree, the grading and the integration
    where they vary."""
    label = "%s Q%d" % (base, degree) if args.degrees != [2] else base
    return label + (", graded %g" % grade if grade != 1 else "") + (", reduced" if integration == "reduced" else "")


def run_ladders(args):
    """Every run, mesh by mesh: ours at each (method, degree, grade), then each peer at each grade."""
    rows, stopped = [], set()  # stopped: our (method, degree, grade, integration) ladders past --max-wall
    if "fenicsx" in args.peer_list:  # warm FEniCSx's JIT cache so no run pays for compiling forms
        run_fenicsx(1, 1)
    for n in args.ladder:
        for grade in args.grades:
            for k, m, integration in [(k, m, i) for i in args.integrations for k in args.degrees
                                      for m in args.method_list]:
                cap = {"direct": args.direct_max_dofs, "cg-amg": args.amg_max_dofs}.get(m, float("inf"))
                if PROBLEM["dofs"](n, k) > cap or (m, k, grade, integration) in stopped:
                    continue
                r = run_ours(n, m, args.ranks, k, grade, integration)
                r.update(code="compliant", variant=variant_label(m, k, grade, args, integration), n=n, degree=k)
                rows.append(r)
                print(json.dumps(r), flush=True)
                if r.get("wall_s", 0) > args.max_wall or "skipped" in r:
                    stopped.add((m, k, grade, integration))
            if n > args.peer_max_n:
                continue
            for peer in args.peer_list:
                r = run_fenicsx(n, args.ranks, grade) if peer == "fenicsx" else run_calculix(n, grade)
                variant = PROBLEM.get("fenicsx_variant", "gamg") if peer == "fenicsx" else \
                    PROBLEM.get("calculix_variant", "spooles")
                r.update(code=peer, variant=variant + (", graded %g" % grade if grade != 1 else ""), n=n, degree=2)
                rows.append(r)
                print(json.dumps(r), flush=True)
    return rows


def choose_reference(args, done):
    """(reference, how, extrapolations): given, or Richardson on our highest degree's ladder (first
    method, first grade); the methods share the discretisation, so any one of them serves.
    extrapolations: (degree, variant, order, limit, meshes) for every ladder of ours, for the report."""
    ladders = {}
    for r in done:
        if r["code"] == "compliant":
            ladders.setdefault((r["degree"], r["variant"]), []).append(r)
    extrapolations = []
    for (k, variant), rs in sorted(ladders.items()):
        extrapolations.append((k, variant) + reference_from(rs))
        finest = (k, variant) + reference_from(rs, finest=True)
        if finest[4] != extrapolations[-1][4]:
            extrapolations.append(finest)
    first = variant_label(args.method_list[0], max(args.degrees), args.grades[0], args, args.integrations[0])
    top = [e for e in extrapolations if e[0] == max(args.degrees) and e[1] == first]
    if args.reference is not None:
        how = "given (--reference)" + (": " + args.reference_note if args.reference_note else "")
        return args.reference, how, extrapolations
    if not top:
        sys.exit("speed_vs_peers.py: no run of ours to take a reference from")
    k, variant, order, reference, triple = top[0]
    how = "Richardson on our %sn = %s, observed order %.2f" % (
        "Q%d, " % k if args.degrees != [2] else "", triple, order)
    return reference, how, extrapolations


def table_lines(done, groups):
    """The table of every run and the fitted slopes of solve time against DoFs."""
    lines = ["| code | method | n | DoFs | %s | error | wall (s) | solve (s) | iterations | peak MB/rank |" % PROBLEM["label"],
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in done:
        lines.append("| %s | %s | %d | %d | %.7g | %.1e | %.2f | %s | %d | %.0f |" % (
            r["code"], r["variant"], r["n"], r["dofs"], r["qoi"], r["error"], r["wall_s"],
            "-" if math.isnan(r["solve_s"]) else "%.2f" % r["solve_s"], r["iterations"], r["memory_mb"]))
    lines += ["", "Solve time against DoFs (least-squares slope from 1.5e4 DoFs up):", ""]
    for (code, variant), rs in groups.items():
        pts = [(r["dofs"], r["solve_s"] if not math.isnan(r["solve_s"]) else r["wall_s"]) for r in rs if r["dofs"] >= 1.5e4]
        lines.append("- %s %s: slope %.2f over %d meshes%s" % (code, variant, fit_slope(pts), len(pts),
                                                               " (whole process)" if code == "calculix" else ""))
    return lines


def equal_accuracy_lines(groups):
    """Each peer's wall time over ours at the errors of our first ladder's meshes."""
    ours_fast = next((rs for (code, _), rs in groups.items() if code == "compliant"), [])
    lines = ["", "Wall time at equal accuracy (log-log interpolation between meshes), peer / ours (%s):" % (
        ours_fast[0]["variant"] if ours_fast else "-"), ""]
    for target in sorted({r["error"] for r in ours_fast if r["error"] > 0}, reverse=True):
        ours_t = time_at_error(ours_fast, target)
        if math.isnan(ours_t):
            ours_t = min(r["wall_s"] for r in ours_fast if r["error"] == target)
        cells = ["%s %.1f" % (code, time_at_error(rs, target) / ours_t)
                 for (code, variant), rs in groups.items() if code != "compliant"]
        lines.append("- error %.1e: ours %.2f s; %s" % (target, ours_t, ", ".join(cells)))
    return lines


def target_lines(groups, targets):
    """Every ladder's wall time to reach each target error, ours with the ratio to each peer's ladder."""
    peer_groups = [(key, rs) for key, rs in groups.items() if key[0] != "compliant"]
    lines = ["", "Wall time (whole process, s) to reach an error, walking each ladder from coarse to fine "
             "(log-log interpolation between the last mesh above and the first at or below; <= : the "
             "coarsest mesh is already there; - : not reached on the ladder)%s:" % (
                 "; ours / %s in brackets" % " / ".join("%s %s" % k for k, _ in peer_groups) if peer_groups else ""),
             "", "| code | method | " + " | ".join("%g %%" % (100 * t) for t in targets) + " |",
             "|---|---|" + "---|" * len(targets)]
    reach = {key: [time_to_reach(rs, t) for t in targets] for key, rs in groups.items()}
    for key, rs in groups.items():
        cells = []
        for i, (t, note) in enumerate(reach[key]):
            if math.isnan(t):
                cells.append("-")
                continue
            cell = "%s%.2f" % (note, t)
            if key[0] == "compliant":
                ratios = ["%.2f" % (t / reach[pk][i][0]) for pk, _ in peer_groups if not math.isnan(reach[pk][i][0])]
                if ratios:
                    cell += " (%s)" % ", ".join(ratios)
            cells.append(cell)
        lines.append("| %s | %s | %s |" % (key[0], key[1], " | ".join(cells)))
    return lines


def plot(groups, args, name):
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
    fig.savefig(os.path.join(args.out, "%s_speed.png" % name), dpi=120)


def main():
    args = parse_arguments()
    global PROBLEM, PROBLEM_NAME
    PROBLEM, PROBLEM_NAME = PROBLEMS[args.problem], args.problem
    name = args.name or PROBLEM_NAME
    rows = run_ladders(args)
    done = [r for r in rows if "skipped" not in r]
    reference, how, extrapolations = choose_reference(args, done)
    for r in done:
        r["error"] = abs(r["qoi"] - reference) / abs(reference)
    print("\nReference %s %.9g (%s)" % (PROBLEM["label"], reference, how))

    os.makedirs(args.out, exist_ok=True)
    keys = ["code", "variant", "n", "dofs", "qoi", "error", "wall_s", "solve_s", "iterations", "memory_mb"]
    if args.degrees != [2]:
        keys.insert(2, "degree")
    with open(os.path.join(args.out, "%s_speed.csv" % name), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys + ["method", "skipped"], extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)
    groups = {}
    for r in done:
        groups.setdefault((r["code"], r["variant"]), []).append(r)
    lines = table_lines(done, groups) + equal_accuracy_lines(groups)
    targets = [float(v) for v in args.targets.split(",") if v]
    if targets:
        lines += target_lines(groups, targets)
    if len(extrapolations) > 1 or args.reference is not None:
        lines += ["", "Richardson extrapolation of each of our ladders (the three finest meshes of a halving ladder, "
                  "and the finest three):", ""]
        for k, variant, order, limit, triple in extrapolations:
            lines.append("- %s: n = %s, observed order %.2f, limit %.9g (%+.1e against the reference)" % (
                variant, triple, order, limit, (limit - reference) / abs(reference)))
    for r in rows:
        if "skipped" in r:
            lines.append("- skipped %s %s n=%d: %s" % (r["code"], r["variant"], r["n"], r["skipped"]))
    text = "\n".join(lines)
    with open(os.path.join(args.out, "%s_speed.md" % name), "w") as f:
        f.write("\n".join(["# Speed against accuracy: %s" % PROBLEM["title"], ""] + provenance()) + "\n" +
                "Reference %s %.9g (%s); %d ranks.\n\n" % (PROBLEM["label"], reference, how, args.ranks) +
                text + "\n")
    print(text)
    plot(groups, args, name)


if __name__ == "__main__":
    sys.exit(main())
