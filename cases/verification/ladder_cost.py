#!/usr/bin/python3
"""What the model ladder costs against the cheapest uniform mesh that meets the same target.

For each problem: one ladder run (Target/Relative error), then a brute-force sweep of uniform
refinements of the same starting mesh (each its own process, no target), the cheapest of which
within the target of the reference is the yardstick. Cost is whole-process wall time (what a user
waits for, start-up included) and, beside it, the solver's own time (sum of the rungs' set-up to
quantities, against the one run's time_total). Writes cases/verification/ladder_cost.{md,csv}.

  /usr/bin/python3 cases/verification/ladder_cost.py [--target 0.5]

References: exact (2D cantilever, Timoshenko-Goodier), Saint-Venant series (torsion bar J), and
converged values from uniform Q2 Richardson where no closed form is exact: Cook's membrane 23.9677
(to 132k DoFs; the literature's 23.96 agrees to its 4 digits); the slender flexure hinge of
cases/flexure_hinge.prm 3.4341 N mm/rad (3.4455, 3.4394, 3.4365 at 73k, 290k, 1.15M DoFs, observed
order 1.1 from the notch corners: extrapolated 3.4341 +- 0.0005); the elastica tip deflection of
cases/verification/elastica_tip_load.prm from 10 x 1 cells, 30.174142 (5 refinements, 83k DoFs).
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402

PROBLEMS = [
    # name, case, quantity, reference (None: from Comparison), starting sets, extra ladder sets
    ("2D cantilever Q1 (exact)", "cantilever_2d_exact.prm", "displacement_tip_y", None,
     ["Geometry/Parameters/ny=1", "Discretization/Element degree=1"], []),
    ("2D cantilever Q2 (exact)", "cantilever_2d_exact.prm", "displacement_tip_y", None,
     ["Geometry/Parameters/ny=1", "Discretization/Element degree=2"], []),
    ("Cook's membrane Q2, uniform", "cook_membrane_linear.prm", "displacement_mid_y", 23.9677,
     ["Geometry/Parameters/n=4"], ["Target/Allow finite strain=false"]),
    ("Cook's membrane Q2, adaptive", "cook_membrane_linear.prm", "displacement_mid_y", 23.9677,
     ["Geometry/Parameters/n=4"], ["Target/Allow finite strain=false", "Target/Refinement=adaptive",
                                   "Target/Maximum refinements=10"]),
    ("flexure hinge stiffness, 2D Q2 (converged)", "../flexure_hinge.prm", "rotational_stiffness_drive", 3.4341,
     [], []),
    ("torsion bar J, 3D Q2, uniform rungs (Saint-Venant series)", "torsion_bar.prm", "J", None,
     ["Geometry/Parameters/nx=30", "Geometry/Parameters/ny=6", "Geometry/Parameters/nz=1"],
     ["Target/Refinement=uniform"]),
    # Degree rungs (Target/Refinement = degree): 2, 3, 4 on the starting mesh, then halved cells.
    ("Cook's membrane, degree rungs", "cook_membrane_linear.prm", "displacement_mid_y", 23.9677,
     ["Geometry/Parameters/n=4"], ["Target/Allow finite strain=false", "Target/Refinement=degree"]),
    # The default in 3D (Target/Refinement = auto): degree rungs on hexahedra.
    ("torsion bar J, 3D, default (degree rungs)", "torsion_bar.prm", "J", None,
     ["Geometry/Parameters/nx=30", "Geometry/Parameters/ny=6", "Geometry/Parameters/nz=1"], []),
    ("thick cylinder bore hoop stress, 3D Q2, uniform rungs (Lame)", "lame_cylinder_3d.prm", "stress_bore_yy", None,
     [], ["Target/Refinement=uniform"]),
    ("thick cylinder bore hoop stress, 3D, default (degree rungs)", "lame_cylinder_3d.prm", "stress_bore_yy", None,
     [], []),
    # Finite strain: the ladder starts linear (Analysis=linear static), the sweep runs the case's
    # own nonlinear analysis. Reference: the converged continuum (5 refinements, 83k DoFs).
    ("elastica tip deflection, finite strain 2D Q2 (converged)", "elastica_tip_load.prm", "displacement_tip_y",
     30.174142, ["Geometry/Parameters/nx=10", "Geometry/Parameters/ny=1"], ["Analysis=linear static"]),
]


def run(case, sets):
    out = tempfile.mkdtemp(prefix="ladder-cost-")
    cmd = ["mpirun", "-np", "2", solver_path(), os.path.join(HERE, case), "--set", "Output/Directory=" + out,
           "--set", "Output/Fields=false"] + sum([["--set", s] for s in sets], [])
    start = time.perf_counter()
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    wall = time.perf_counter() - start
    summary_file = os.path.join(out, "summary.json")
    summary = json.load(open(summary_file)) if os.path.exists(summary_file) else None
    rows = list(csv.DictReader(open(os.path.join(out, "ladder.csv")))) if os.path.exists(os.path.join(out, "ladder.csv")) else []
    subprocess.run(["rm", "-rf", out])
    if summary is None:
        raise RuntimeError("%s %s failed: %s" % (case, sets, proc.stderr[-500:]))
    return wall, summary, rows, proc.returncode


def reference_of(summary, quantity, given):
    if given is not None:
        return given
    return [c for c in summary["comparisons"] if c["quantity"] == quantity][0]["reference"]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--target", type=float, default=0.5, help="percent")
    parser.add_argument("--max-refinements", type=int, default=4, help="uniform sweep depth")
    args = parser.parse_args()
    target = args.target / 100
    lines, table = [], []
    for name, case, quantity, given, start_sets, ladder_sets in PROBLEMS:
        wall, summary, rows, rc = run(case, start_sets + ladder_sets + [
            "Target/Relative error=%g" % args.target, "Target/Quantities=" + quantity])
        reference = reference_of(summary, quantity, given)
        value = summary["quantities"][quantity]
        ladder_true = abs(value - reference) / abs(reference)
        solver_seconds = sum(float(r["seconds"]) for r in rows)
        sweep = None
        for k in range(args.max_refinements + 1):
            w, s, _, _ = run(case, start_sets + ["Discretization/Global refinements=%d" % k])
            true = abs(s["quantities"][quantity] - reference) / abs(reference)
            print("  %s: uniform +%d: %d DoFs, error %.3g %%, %.2f s" % (name, k, s["quantities"]["n_dofs"], 100 * true, w))
            if true <= target:
                sweep = (k, s["quantities"]["n_dofs"], true, w, s["quantities"]["time_total"])
                break
        row = dict(problem=name, target_percent=args.target, ladder_rungs=len(rows), ladder_dofs=summary["quantities"]["n_dofs"],
                   ladder_true_error=ladder_true, ladder_estimate=summary["quantities"].get(quantity + "_error_estimate", ""),
                   ladder_met=(rc == 0 and ladder_true <= target), ladder_wall=wall, ladder_solver_seconds=solver_seconds)
        if sweep:
            row.update(uniform_refinements=sweep[0], uniform_dofs=sweep[1], uniform_true_error=sweep[2],
                       uniform_wall=sweep[3], uniform_solver_seconds=sweep[4],
                       wall_ratio=wall / sweep[3], solver_ratio=solver_seconds / sweep[4])
        table.append(row)
        print(row)
    with open(os.path.join(HERE, "ladder_cost.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(table[0].keys()) + [k for k in ("uniform_refinements", "uniform_dofs",
                                "uniform_true_error", "uniform_wall", "uniform_solver_seconds", "wall_ratio", "solver_ratio")
                                if k not in table[0]])
        writer.writeheader()
        writer.writerows(table)
    lines.append("Model ladder against the cheapest uniform mesh meeting a %g %% target (2 ranks; `%s`)." %
                 (args.target, "/usr/bin/python3 cases/verification/ladder_cost.py --target %g" % args.target))
    lines.append("")
    lines.append("| problem | ladder: rungs, DoFs, true error, estimate, met | cheapest uniform: DoFs, true error | whole process: ladder / uniform | solver time: ladder / uniform |")
    lines.append("|---|---|---|---|---|")
    for r in table:
        est = "%.3g %%" % (100 * r["ladder_estimate"]) if r["ladder_estimate"] != "" else "-"
        uniform = ("%d, %.3g %%" % (r["uniform_dofs"], 100 * r["uniform_true_error"])) if "uniform_dofs" in r else "none within the sweep"
        ratios = ("%.2f / %.2f s = %.2f" % (r["ladder_wall"], r["uniform_wall"], r["wall_ratio"]),
                  "%.3f / %.3f s = %.2f" % (r["ladder_solver_seconds"], r["uniform_solver_seconds"], r["solver_ratio"])) if "uniform_dofs" in r else ("-", "-")
        lines.append("| %s | %d, %d, %.3g %%, %s, %s | %s | %s | %s |" % (
            r["problem"], r["ladder_rungs"], r["ladder_dofs"], 100 * r["ladder_true_error"], est,
            "yes" if r["ladder_met"] else "NO", uniform, ratios[0], ratios[1]))
    open(os.path.join(HERE, "ladder_cost.md"), "w").write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
