#!/usr/bin/python3
"""Rung (b) of the model ladder: the out-of-plane bound of a plane-stress answer against the 3D solid.

The plane-stress cantilever of cases/verification/cantilever_2d.prm (100 x 10, tip force) with
thickness W = 1, 10, 40 climbs the ladder; its summary holds out_of_plane_bound, the bound on
|U_3D - U_ps| / U_ps from the two energy principles (quantities/out_of_plane_bound.h). The same part
is solved as a 3D solid (cases/verification/cantilever_3d.prm, Q2). The mean deflection of the loaded
face is work-conjugate to the single load (2 U / F), so its relative gap is the energy's. Checked:
  - the 3D part is at least as stiff as plane stress (static principle), up to the 3D mesh's own
    error (Q2, stiff by < 0.06 % on these meshes: -0.0020014347 at 8 x 8 against -0.002000336 at 4 x 4);
  - the true gap is within the bound, and the bound is not vacuous: at most 8 times the gap
    (measured 1.2, 5.0 and 3.8 for W = 1, 10, 40: the clamp's anticlastic layer costs most of it;
    at W = 1 the finer 3D mesh would bring the gap from 0.11 % to about 0.08 %);
  - the ladder says 2D is enough at W = 1 (bound 0.13 % < 0.5 %) and asks for 3D at W = 10 and 40.
Across dimensions (Target/Paired model, ladder/paired_model.h), each against the 3D solid above:
  - the 3D cantilever at W = 1 paired with its plane-stress model stops in 2D (bound plus
    discretization estimate within 0.5 %), and the 2D answer is within 0.5 % of the 3D solid and
    within bound + estimate (+ 0.06 %, the 3D reference's own error);
  - at W = 10 the same pair climbs the 3D model, which meets 0.5 % against the solid, and the summary
    keeps the plane-stress bound that sent it there; a plane-stress case at W = 40 paired with its
    3D part goes on to the 3D model the same way;
  - a pair that is not the same part (thickness 1 against W = 10) is refused: exit 2, a message
    naming Target/Paired model and both volumes, and no summary written.
The README's tables (plane stress, 3D solid, true gap, bound for W = 1, 10, 40; the paired runs' bounds,
rungs, DoFs and errors against the solid) are asserted to 3 units of the last digit of each figure
(issue 34); the times in the cost column are not.
"""
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish, readme_figure  # noqa: E402

cases = sys.argv[1]


def run_any(case, sets):
    out = tempfile.mkdtemp(prefix="oop-")
    cmd = ["mpirun", "-np", "2", solver_path(), os.path.join(cases, "verification", case),
           "--set", "Output/Directory=" + out] + sum([["--set", s] for s in sets], [])
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    path = os.path.join(out, "summary.json")
    summary = json.load(open(path)) if os.path.exists(path) else None
    ladder = os.path.join(out, "ladder.csv")
    proc.ladder_rows = list(csv.DictReader(open(ladder))) if os.path.exists(ladder) else []
    subprocess.run(["rm", "-rf", out])
    return proc, summary


def run(case, sets):
    proc, summary = run_any(case, sets)
    if proc.returncode != 0 or summary is None:
        sys.exit("run failed: %s %s\n%s%s" % (case, sets, proc.stdout[-3000:], proc.stderr[-2000:]))
    return proc.stdout, summary


# 3D meshes: ny cells through the depth, nz across the width (Q2); at W = 1 the 3D mesh must be
# fine (ny = 8) as its own stiffness error (0.1 % at ny = 4) is as large as the gap.
solid_reference = {}
# README: plane stress, 3D solid, true gap, bound (each with 3 units of its last printed digit)
README = {1: ((-0.02012032, 3e-8), (-0.02009823, 3e-8), (0.00110, 3e-5), (0.00127, 3e-5)),
          10: ((-0.002012032, 3e-9), (-0.002000336, 3e-9), (0.00581, 3e-5), (0.0289, 3e-4)),
          40: ((-0.000503008, 3e-9), (-0.000489768, 3e-9), (0.0263, 3e-4), (0.0990, 3e-4))}
for width, ny, nz in ((1, 8, 2), (10, 4, 4), (40, 4, 8)):
    log, plane = run("cantilever_2d.prm", ["Material/Thickness=%g" % width, "Target/Relative error=0.5",
                                           "Target/Closed forms=false"])
    _, solid = run("cantilever_3d.prm", ["Geometry/Parameters/W=%g" % width, "Geometry/Parameters/ny=%d" % ny,
                                          "Geometry/Parameters/nz=%d" % nz])
    u2 = plane["quantities"]["mean_displacement_right_y"]
    u3 = solid["quantities"]["mean_displacement_right_y"]
    solid_reference[width] = u3
    bound = plane["quantities"]["out_of_plane_bound"]
    gap = (abs(u2) - abs(u3)) / abs(u2)
    print("W = %g: plane stress %.8g, 3D %.8g, gap %.3f %%, bound %.3f %% (bound / gap %.1f)" % (
        width, u2, u3, 100 * gap, 100 * bound, bound / gap if gap > 0 else float("inf")))
    check(gap > -5e-4, "W = %g: the 3D part is at least as stiff as plane stress (gap %.3g)" % (width, gap))
    check(gap <= bound, "W = %g: the gap %.3g is within the bound %.3g" % (width, gap, bound))
    check(bound <= 8 * max(gap, 1e-4), "W = %g: the bound %.3g is at most 8 x the gap %.3g" % (width, bound, gap))
    enough = bound <= 0.005
    check(("2D is enough" in log) == enough and ("model it in 3D" in log) != enough,
          "W = %g: the ladder's rung (b) says %s" % (width, "2D is enough" if enough else "model it in 3D"))
    check(("ladder_dimension_check" in plane["settings"]), "W = %g: summary.json holds the dimension check" % width)
    for what, value, (figure, tolerance) in zip(("plane stress", "3D solid", "true gap", "bound"),
                                                (u2, u3, gap, bound), README[width]):
        check(abs(value - figure) <= tolerance, "W = %g: %s %.9g is the README's %.9g (+- %.1g)"
              % (width, what, value, figure, tolerance))

# Across dimensions: the ladder chooses 2D or 3D itself.
target = ["Target/Relative error=0.5"]
pair_2d = "Target/Paired model=cantilever_2d.prm: Material/Thickness=W"
proc, summary = run_any("cantilever_3d.prm", target + [pair_2d, "Geometry/Parameters/W=1", "Geometry/Parameters/nz=1"])
q = summary["quantities"] if summary else {}
# A missing summary or quantity fails here instead of reading as zero below.
check(all(k in q for k in ("mean_displacement_right_y", "out_of_plane_bound", "mean_displacement_right_y_error_estimate",
                           "mean_displacement_right_y_error_estimate_against_3d")),
      "W = 1: summary.json with the displacement, the out-of-plane bound and both estimates")
u = q.get("mean_displacement_right_y", float("nan"))
error = abs(u - solid_reference[1]) / abs(solid_reference[1])
allowed = q.get("out_of_plane_bound", float("nan")) + q.get("mean_displacement_right_y_error_estimate", float("nan")) + 6e-4
print("W = 1, 3D case paired with plane stress: %s, %.8g, error against the solid %.3f %%, bound + estimate %.3f %%" % (
    summary["case"] if summary else "-", u, 100 * error, 100 * (allowed - 6e-4)))
check(proc.returncode == 0 and summary["case"].endswith("cantilever_2d.prm"),
      "W = 1: the 3D case stops at its plane-stress model")
check(error <= 0.005 and error <= allowed, "W = 1: the 2D answer is within the target and bound + estimate of the solid")
check(abs(q.get("mean_displacement_right_y_error_estimate_against_3d", float("nan")) - (allowed - 6e-4)) < 1e-12,
      "W = 1: summary.json gives the error estimate against the 3D part, estimate + bound")
# README: "2D: bound 0.13 %, 3 rungs to 21k DoFs | 0.110 % (bound + estimate 0.131 %)"
readme_figure(q.get("out_of_plane_bound", float("nan")), "0.13", "W = 1 paired: bound in %", 100)
check(q.get("ladder_rungs") == 3 and len(proc.ladder_rows) == 3, "W = 1 paired: 3 rungs (%s)" % q.get("ladder_rungs"))
readme_figure(q.get("n_dofs", float("nan")), "21", "W = 1 paired: thousands of DoFs", 1e-3)
readme_figure(error, "0.110", "W = 1 paired: error against the 3D solid in %", 100)
readme_figure(allowed - 6e-4, "0.131", "W = 1 paired: bound + estimate in %", 100)

# README: "the 3D ladder alone ... (41k DoFs, 0.028 %)", the error against the solid.
proc, summary = run_any("cantilever_3d.prm", target + ["Geometry/Parameters/W=1", "Geometry/Parameters/nz=1"])
q = summary["quantities"] if summary else {}
check(proc.returncode == 0 and summary is not None, "W = 1: the 3D ladder alone runs")
readme_figure(q.get("n_dofs", float("nan")), "41", "W = 1, 3D ladder alone: thousands of DoFs", 1e-3)
readme_figure(abs(q.get("mean_displacement_right_y", float("nan")) - solid_reference[1]) / abs(solid_reference[1]),
              "0.028", "W = 1, 3D ladder alone: error against the solid in %", 100)

# A target below the first rung's bound (0.24 %) but above the converged one (0.13 %): the bound
# tightens on the 2D rungs and 2D is kept.
proc, summary = run_any("cantilever_3d.prm", ["Target/Relative error=0.15", pair_2d, "Geometry/Parameters/W=1",
                                              "Geometry/Parameters/nz=1"])
u = summary["quantities"]["mean_displacement_right_y"] if summary else 0
error = abs(u - solid_reference[1]) / abs(solid_reference[1])
print("W = 1, target 0.15 %%: %s, error against the solid %.3f %%" % (summary["case"] if summary else "-", 100 * error))
check(proc.returncode == 0 and summary["case"].endswith("cantilever_2d.prm") and error <= 0.0015,
      "W = 1, target 0.15 %: the bound tightens below the target on finer 2D rungs, 2D kept and within 0.15 %")
# README: "bound 0.24, 0.16, 0.13 % on the three 2D rungs | 0.110 %" (the bounds as the log prints them)
bounds = re.findall(r"\|U_3D - U\| <= ([0-9.eE+-]+) % of U", proc.stdout)
check(len(bounds) == 3, "W = 1, target 0.15 %%: the log gives a bound on each of three 2D rungs (%s)" % bounds)
for b, figure in zip(bounds, ("0.24", "0.16", "0.13")):
    readme_figure(float(b), figure, "W = 1, target 0.15 %: rung bound in %")
readme_figure(error, "0.110", "W = 1, target 0.15 %: error against the 3D solid in %", 100)

# The case's --set materials carry over to its pair: half the modulus, twice the deflection.
proc, softer = run_any("cantilever_3d.prm", target + [pair_2d, "Geometry/Parameters/W=1", "Geometry/Parameters/nz=1",
                                                       "Material/Materials=*: steel, E=100000, nu=0.3"])
ratio = softer["quantities"]["mean_displacement_right_y"] / u if softer else 0
check(proc.returncode == 0 and abs(ratio - 2) < 1e-3,
      "--set Material/Materials of the case reaches its plane-stress model (deflection ratio %.6f)" % ratio)

proc, summary = run_any("cantilever_3d.prm", target + [pair_2d])
q = summary["quantities"] if summary else {}
error = abs(q.get("mean_displacement_right_y", 0) - solid_reference[10]) / abs(solid_reference[10])
print("W = 10, 3D case paired with plane stress: %s, error against the solid %.3f %%" % (
    summary["case"] if summary else "-", 100 * error))
check(proc.returncode == 0 and summary["case"].endswith("cantilever_3d.prm") and
      q.get("out_of_plane_bound", 0) > 0.005 and "ladder_dimension_check" in summary["settings"],
      "W = 10: the 3D case climbs its own model, with the plane-stress bound that sent it there")
check(error <= 0.005, "W = 10: the 3D answer meets the target against the solid")
# README: "3D: bound 2.9 % after one 2D rung (1458 DoFs) | 0.070 %"
readme_figure(q.get("out_of_plane_bound", float("nan")), "2.9", "W = 10 paired: bound in %", 100)
check([r["dofs"] for r in proc.ladder_rows[:1]] == ["1458"], "W = 10 paired: the one 2D rung has 1458 DoFs")
readme_figure(error, "0.070", "W = 10 paired: error against the 3D solid in %", 100)
models = [r["model"] for r in proc.ladder_rows]
check(models[:1] == ["plane stress linear"] and len(models) == q.get("ladder_rungs") and "linear" in models[1:],
      "W = 10: ladder.csv and ladder_rungs hold the abandoned plane-stress rung and the 3D rungs (%s)" % models)

proc, summary = run_any("cantilever_2d.prm", target + [
    "Material/Thickness=40", "Target/Paired model=cantilever_3d.prm: Geometry/Parameters/W=thickness, Geometry/Parameters/nz=8"])
q = summary["quantities"] if summary else {}
error = abs(q.get("mean_displacement_right_y", 0) - solid_reference[40]) / abs(solid_reference[40])
print("W = 40, plane-stress case paired with its 3D part: %s, error against the solid %.3f %%" % (
    summary["case"] if summary else "-", 100 * error))
check(proc.returncode == 0 and summary["case"].endswith("cantilever_3d.prm") and error <= 0.005,
      "W = 40: the plane-stress case goes on to its 3D part and meets the target against the solid")
# README: "3D: bound 9.9 % | 0.068 %"
readme_figure(q.get("out_of_plane_bound", float("nan")), "9.9", "W = 40 paired: bound in %", 100)
readme_figure(error, "0.068", "W = 40 paired: error against the 3D solid in %", 100)

proc, summary = run_any("cantilever_3d.prm", target + ["Target/Paired model=cantilever_2d.prm"])
check(proc.returncode == 2 and "Target/Paired model" in proc.stderr and "same part" in proc.stderr and summary is None,
      "a pair that is not the same part is refused with exit 2, naming the entry, no output: " + proc.stderr.strip()[:160])

finish()
