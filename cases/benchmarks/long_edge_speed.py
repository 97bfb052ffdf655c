#!/usr/bin/python3
"""The long-edge coarse space (Linear solver/Coarse space = auto, the default) against the degree-1
level it replaces on long cells (Coarse space = degree-1) and against MUMPS on the whole system
(Method = direct), on thin parts, alternately in the same run, 2 ranks.

Models: the thin torsion bar (a/b = 6, cells 12 : 1, the mesh of case.torsion_saint_venant_ab6) at
three refinements, a plate of cells long in two directions, the thin leaf of leaf_torsion.prm
(cells 8 : 1 : 1), the 3D blade hinge of hinge_3d.prm (uniform m = 2, and graded 10 with reduced
integration at m = 2 and 3, the meshes of speed_vs_peers.py --problem hinge --grade 10) and the
finite-strain strip on cells 4 : 1 (Newton, the tangent's p-multigrid). For each: outer CG
iterations (all Newton steps' for the strip), the solve time (`time_solve`, or `time_linear_solves`
for the strip: the factorization included for MUMPS), the process's own total (`time_total`:
assembly where a method needs one, set-up, solve) and the whole process (`mpirun` wall time), each
the median of --repeat runs; and the answer of each method (they must agree to the solver's
tolerance). MUMPS is left out above --direct-max-dofs (its 3D factor grows much faster than N).

  /usr/bin/python3 cases/benchmarks/long_edge_speed.py [--repeat N] [--direct-max-dofs N] [--out DIR]
"""
import argparse
import re
import os
import statistics
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "postproc"))
from report_header import provenance, timed_run  # noqa: E402
from study import mpi_env, solver_path  # noqa: E402

sys.path.insert(0, os.path.join(HERE, "peers"))
import hinge_mesh  # noqa: E402

BAR = os.path.join(ROOT, "cases", "verification", "torsion_bar.prm")
# The graded hinge meshes of speed_vs_peers.py --problem hinge --grade 10 (written by main).
HINGE_GRADED = os.path.join(tempfile.gettempdir(), "long_edge_hinge_m2_graded10.inp")
HINGE_GRADED_3 = os.path.join(tempfile.gettempdir(), "long_edge_hinge_m3_graded10.inp")
BAR_SETS = ["Geometry/Parameters/H=6", "Geometry/Parameters/W=1", "Geometry/Parameters/L=120", "Comparison/Checks="]


def cells(nx, ny, nz):
    return ["Geometry/Parameters/nx=%d" % nx, "Geometry/Parameters/ny=%d" % ny, "Geometry/Parameters/nz=%d" % nz]


# name, case, settings, the answer compared, the solve time's key
MODELS = [
    ("thin torsion bar 20 x 7 x 2 (12:1 cells)", BAR, BAR_SETS + cells(20, 7, 2), "J", "time_solve"),
    ("thin torsion bar 40 x 14 x 4 (12:1 cells)", BAR, BAR_SETS + cells(40, 14, 4), "J", "time_solve"),
    ("thin torsion bar 80 x 28 x 8 (12:1 cells)", BAR, BAR_SETS + cells(80, 28, 8), "J", "time_solve"),
    ("plate 80 x 40 x 1 in torsion, 20 x 10 x 2 cells (8:8:1)", BAR,
     ["Geometry/Parameters/H=40", "Geometry/Parameters/W=1", "Geometry/Parameters/L=80", "Comparison/Checks="] +
     cells(20, 10, 2), "J", "time_solve"),
    ("thin leaf in torsion, 10 x 20 x 2 cells (8:1:1)", os.path.join(HERE, "leaf_torsion.prm"), cells(10, 20, 2),
     "strain_energy", "time_solve"),
    ("3D blade hinge, m = 2 (blade cells 4:1:5)", os.path.join(HERE, "hinge_3d.prm"), [],
     "rotational_stiffness_turned", "time_solve"),
    ("3D blade hinge, m = 2, graded 10, reduced", os.path.join(HERE, "hinge_3d.prm"),
     ["Geometry/Mesh file=" + HINGE_GRADED, "Discretization/Integration=reduced"],
     "rotational_stiffness_turned", "time_solve"),
    ("3D blade hinge, m = 3, graded 10, reduced", os.path.join(HERE, "hinge_3d.prm"),
     ["Geometry/Mesh file=" + HINGE_GRADED_3, "Discretization/Integration=reduced"],
     "rotational_stiffness_turned", "time_solve"),
    ("finite-strain strip 10 x 8 x 2 (4:1 cells), 6 load steps", os.path.join(HERE, "flexure_finite_strain.prm"),
     cells(10, 8, 2), "rotational_stiffness_right", "time_linear_solves"),
]
METHODS = [
    ("long-edge space", ["Linear solver/Coarse space=auto"]),
    ("degree-1 level", ["Linear solver/Coarse space=degree-1"]),
    ("MUMPS", ["Linear solver/Method=direct"]),
]


def run(case, sets):
    return timed_run(solver_path(), case, sets, mpi_env())


def lowest_level(note):
    """The p-multigrid's lowest level as its log names it: the long-edge space where `auto` chose it
    (long cells in thin parts only), else the degree-1 level; '-' for MUMPS."""
    match = re.search(r"long-edge space \((\d+) DoFs\)", note)
    return "long-edge space, %s DoFs" % match.group(1) if match else "degree 1" if note else "-"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--repeat", type=int, default=3, help="runs of each method per model (medians count)")
    ap.add_argument("--direct-max-dofs", type=float, default=2e5)
    ap.add_argument("--out", default=HERE)
    args = ap.parse_args()
    hinge_mesh.write_inp(2, HINGE_GRADED, 10.0)
    hinge_mesh.write_inp(3, HINGE_GRADED_3, 10.0)
    rows = ["| model | DoFs | method | lowest level | iterations | solve | total in process | whole process | answer |",
            "|---|---|---|---|---|---|---|---|---|"]
    ratios = []
    for name, case, sets, answer, solve_key in MODELS:
        print("==", name, flush=True)
        runs = {label: [] for label, _ in METHODS}
        n_dofs = None
        for _ in range(args.repeat):
            for label, method in METHODS:
                if label == "MUMPS" and n_dofs is not None and n_dofs > args.direct_max_dofs:
                    continue
                q = run(case, sets + method)
                n_dofs = q["n_dofs"]
                runs[label].append(q)
        medians = {}
        for label, _ in METHODS:
            if not runs[label]:
                rows.append("| %s | %d | %s | - | - | - | - | - | not run (above %.0f DoFs) |" % (
                    name, n_dofs, label, args.direct_max_dofs))
                continue
            qs = runs[label]
            m = {key: statistics.median(q.get(key, float("nan")) for q in qs) for key in (solve_key, "time_total", "wall")}
            iterations = qs[0].get("linear_iterations", qs[0].get("solver_iterations", 0))
            medians[label] = m
            rows.append("| %s | %d | %s | %s | %s | %.3g s | %.3g s | %.3g s | %s = %.10g |" % (
                name, n_dofs, label, lowest_level(qs[0]["note"]), iterations, m[solve_key], m["time_total"],
                m["wall"], answer, qs[0][answer]))
            print(rows[-1], flush=True)
        if "MUMPS" in medians:
            a, d = medians["long-edge space"], medians["MUMPS"]
            ratios.append("| %s | %.2f | %.2f | %.2f |" % (name, a[solve_key] / d[solve_key],
                                                          a["time_total"] / d["time_total"], a["wall"] / d["wall"]))
    report = ["# The long-edge coarse space against the degree-1 level and MUMPS on thin parts", ""] + provenance() + [
        "2 ranks; medians of %d runs of each method, alternating. *solve*: `time_solve` (MUMPS: its "
        "factorization and solve), for the finite-strain strip `time_linear_solves` (all Newton steps); "
        "*total in process*: `time_total` (mesh to answer inside the process: MUMPS also assembles its "
        "matrix); *whole process*: the wall time of `mpirun`. *iterations*: outer CG iterations (all "
        "Newton steps' for the strip); 1 for MUMPS. *method*: the setting (`Coarse space = auto` is "
        "the long-edge space's row); *lowest level*: what the p-multigrid then used (auto keeps the degree-1 "
        "level where long cells lie in thick parts, as in the blade hinge's blocks)." % args.repeat, ""] + rows + [
        "", "Long-edge space / MUMPS (the issue's bar is a third):", "",
        "| model | solve | total in process | whole process |", "|---|---|---|---|"] + ratios + [""]
    path = os.path.join(args.out, "long_edge_speed.md")
    with open(path, "w") as f:
        f.write("\n".join(report))
    print("wrote", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
