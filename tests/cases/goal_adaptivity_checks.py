#!/usr/bin/python3
"""Goal-oriented (dual-weighted) adaptive refinement and the ladder's use of dual-weighted estimates
(issue 28), on problems the ladder's own tests do not use for this:

1. Plate with a circular hole (Kirsch geometry, finite quarter plate, plane stress, Q2), target
   sigma_xx at the hole's edge to 0.1 %: the adaptive ladder with the default goal-oriented
   indicator reaches 0.1 % on at most a third of the DoFs uniform refinement needs for it, and
   stops within the target of the converged value. Reference 3.3600775: degree 3 on three finer
   meshes, extrapolated (cases/verification/error_estimates.md); not the infinite plate's 3 S.
2. The same ladder with Quantities/Error estimates = true: the dual-weighted estimate on every rung
   within 0.5-3 of the true error.
3. Cook's membrane (displacement at (48, 52), converged 23.96774 by FEniCSx): the goal-oriented
   indicator's rungs 4 and 6 are closer to the reference than Kelly's at about the same DoFs.
4. The torsion bar's J = M / (G theta'), a derived target whose parts (a reaction moment, the
   rotations of two sections read from mirror points) share the errors of the bar's ends, which
   cancel in J: its one combined dual refines the section between the measuring points. Against
   the series (1.789917): goal-oriented rungs reach 0.1 % on at most a third of the DoFs of the
   first uniform rung that does (uniform rung 2 is still above 0.1 %, so uniform needs at least
   rung 3: 241 x 49 x 9 nodes x 3 components).
5. The rotation of Cook's loaded edge (Quantities/Rotations, its least-squares rigid fit over the
   edge), against 0.8456745 (degree 3 on 32 x 32 cells refined three times; 0.84567055 refined
   twice): its goal-oriented rungs have a dual of their own and converge to it, and the dual-weighted
   estimate of one run is within 0.5-3 of its true error.
6. Finite strain: the flexure hinge driven to 40 degrees, target 0.5 % on its rotational stiffness,
   adaptive: after the linear rung the finite-strain rungs refine by the duals of the tangent at
   each converged state (a reaction's dual, j = K_T psi), and stop within the target of the
   converged 9.0838 (adaptive rungs at degrees 2 and 3 on 115k and 130k DoFs, 9.0843 both,
   extrapolated) on at most half of the 18.7k DoFs at which the uniform finite-strain rungs stop
   (case.model_ladder).
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish, readme_figure  # noqa: E402

cases = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "verification")
KIRSCH = 3.3600775
COOK = 23.96774
COOK_ROTATION = 0.8456745


def ladder(case, sets, linear_only=True):
    out = tempfile.mkdtemp(prefix="goal-")
    cmd = ["mpirun", "-np", "2", solver_path(), os.path.join(cases, case), "--set", "Output/Directory=" + out,
           "--set", "Output/Fields=false"] + (["--set", "Target/Allow finite strain=false"] if linear_only else []) + \
        sum([["--set", s] for s in sets], [])
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    path = os.path.join(out, "ladder.csv")
    rows = list(csv.DictReader(open(path))) if os.path.exists(path) else []
    summary_path = os.path.join(out, "summary.json")
    summary = json.load(open(summary_path)) if os.path.exists(summary_path) else None
    subprocess.run(["rm", "-rf", out])
    return proc, rows, summary


def true_errors(rows, quantity, reference):
    return [(int(r["dofs"]), abs(float(r[quantity]) - reference) / abs(reference)) for r in rows]


hole = ["Target/Quantities=stress_edge_xx", "Target/Relative error=0.1", "Target/Maximum refinements=8"]
proc, goal_rows, summary = ladder("plate_hole_kirsch.prm", hole + ["Target/Refinement=adaptive"])
check(proc.returncode == 0 and len(goal_rows) > 0, "Kirsch goal-oriented: ladder met, exit %d" % proc.returncode)
check("stress_edge_xx, one dual" in proc.stdout, "Kirsch goal-oriented: the log says the target has a dual")
proc, uniform_rows, _ = ladder("plate_hole_kirsch.prm", hole + ["Target/Refinement=uniform"])
check(proc.returncode == 0 and len(uniform_rows) > 0, "Kirsch uniform: ladder met, exit %d" % proc.returncode)
goal = true_errors(goal_rows, "stress_edge_xx", KIRSCH)
uniform = true_errors(uniform_rows, "stress_edge_xx", KIRSCH)
for name, errors in (("goal", goal), ("uniform", uniform)):
    print("  Kirsch %s: " % name + ", ".join("%d DoFs %.3g %%" % (n, 100 * e) for n, e in errors))
first_goal = next((n for n, e in goal if e <= 0.001), None)
first_uniform = next((n for n, e in uniform if e <= 0.001), None)
if check(first_goal is not None and first_uniform is not None, "Kirsch: both reach 0.1 %"):
    # README: 3114 DoFs against 12610 (0.25)
    check(first_goal <= first_uniform / 3, "Kirsch: goal-oriented reaches 0.1 %% on %d DoFs, uniform on %d (%.2f <= 1/3)"
          % (first_goal, first_uniform, first_goal / first_uniform))
    readme_figure(first_goal / first_uniform, "0.25", "Kirsch: DoF ratio goal-oriented / uniform at 0.1 %")
    check((first_goal, first_uniform) == (3114, 12610), "Kirsch: %d and %d DoFs (README 3114 and 12610)"
          % (first_goal, first_uniform))
    readme_figure(100 * dict(goal)[first_goal], "0.067", "Kirsch goal-oriented at 0.1 %: true error %")
    readme_figure(100 * dict(uniform)[first_uniform], "0.066", "Kirsch uniform at 0.1 %: true error %")
check(goal[-1][1] <= 0.001, "Kirsch goal-oriented: stops within the target (%.3g %%)" % (100 * goal[-1][1]))

proc, rows, summary = ladder("plate_hole_kirsch.prm", hole + ["Target/Refinement=adaptive", "Quantities/Error estimates=true"])
check(proc.returncode == 0 and summary is not None, "Kirsch with dual estimates: ladder met, exit %d" % proc.returncode)
duals = [float(x) for x in __import__("re").findall(r"dual-weighted ([0-9.e+-]+) %", proc.stdout)]
check(len(duals) == len(rows) and len(rows) > 0, "Kirsch: a dual-weighted estimate on every rung (%d of %d)" % (len(duals), len(rows)))
for r, d, text in zip(rows, duals, ("0.87", "0.93", "0.96", "0.93")):  # README: the four rungs' effectivities
    true = abs(float(r["stress_edge_xx"]) - KIRSCH) / KIRSCH
    check(0.5 <= d / 100 / true <= 3, "Kirsch rung %s: dual-weighted %.3g %% against true %.3g %% (effectivity %.2f)"
          % (r["rung"], d, 100 * true, d / 100 / true))
    # the log prints two digits of the estimate: the effectivity is known to about 3 %
    readme_figure(d / 100 / true, text, "Kirsch rung %s: dual-weighted effectivity" % r["rung"], 1.0)
if summary is not None:
    check("stress_edge_xx_dual_error_estimate" in summary["quantities"], "Kirsch: summary has the dual estimate")

cook = ["Target/Quantities=displacement_mid_y", "Geometry/Parameters/n=4", "Target/Refinement=adaptive",
        "Target/Relative error=0.01", "Target/Maximum refinements=6"]
_, goal_rows, _ = ladder("cook_membrane_linear.prm", cook)
_, kelly_rows, _ = ladder("cook_membrane_linear.prm", cook + ["Target/Refinement indicator=kelly"])
goal = true_errors(goal_rows, "displacement_mid_y", COOK)
kelly = true_errors(kelly_rows, "displacement_mid_y", COOK)
readme = {3: ("0.0148", 972, "0.0252", 962), 5: ("0.0044", 3352, "0.0062", 3440)}
for k in (3, 5):  # rungs 4 and 6
    if check(len(goal) > k and len(kelly) > k, "Cook: rung %d in both ladders" % (k + 1)):
        check(goal[k][1] < kelly[k][1] and goal[k][0] <= 1.1 * kelly[k][0],
              "Cook rung %d: goal-oriented %.3g %% on %d DoFs, Kelly %.3g %% on %d DoFs"
              % (k + 1, 100 * goal[k][1], goal[k][0], 100 * kelly[k][1], kelly[k][0]))
        goal_error, goal_dofs, kelly_error, kelly_dofs = readme[k]
        readme_figure(100 * goal[k][1], goal_error, "Cook rung %d goal-oriented: true error %%" % (k + 1))
        readme_figure(100 * kelly[k][1], kelly_error, "Cook rung %d Kelly: true error %%" % (k + 1))
        check((goal[k][0], kelly[k][0]) == (goal_dofs, kelly_dofs), "Cook rung %d: %d and %d DoFs (README %d and %d)"
              % (k + 1, goal[k][0], kelly[k][0], goal_dofs, kelly_dofs))
bar = ["Target/Quantities=J", "Target/Relative error=0.01", "Geometry/Parameters/nx=30",
       "Geometry/Parameters/ny=6", "Geometry/Parameters/nz=1"]
proc, goal_rows, _ = ladder("torsion_bar.prm", bar + ["Target/Refinement=adaptive", "Target/Maximum refinements=2"])
check("reaction_moment_right_x (reaction), one dual" in proc.stdout, "torsion bar: J's parts combined in one dual")
_, uniform_rows, _ = ladder("torsion_bar.prm", bar + ["Target/Refinement=uniform", "Target/Maximum refinements=1"])
goal = true_errors(goal_rows, "J", 1.789917)
uniform = true_errors(uniform_rows, "J", 1.789917)
uniform_rung_3 = (2 * 120 + 1) * (2 * 24 + 1) * (2 * 4 + 1) * 3  # Q2 nodes of 120 x 24 x 4 hexahedra
if check(len(goal) == 3 and len(uniform) == 2, "torsion bar: three goal-oriented and two uniform rungs"):
    print("  torsion bar goal: %s; uniform: %s" % (goal, uniform))
    check(uniform[1][1] > 1e-3, "torsion bar: uniform rung 2 still %.4g %% off on %d DoFs, so uniform needs rung 3 "
          "(%d DoFs)" % (100 * uniform[1][1], uniform[1][0], uniform_rung_3))
    first = next(((d, e) for d, e in goal if e <= 1e-3), None)
    check(first is not None and first[0] <= uniform_rung_3 / 3,
          "torsion bar: goal-oriented rungs reach 0.1 %% on %s DoFs, at most a third of uniform's %d"
          % (first, uniform_rung_3))
    readme_figure(100 * goal[2][1], "0.0098", "torsion bar goal-oriented rung 3: true error %")
    readme_figure(100 * uniform[1][1], "0.121", "torsion bar uniform rung 2: true error %")
    check((goal[1][0], goal[2][0], uniform[1][0]) == (19995, 56619, 45375),
          "torsion bar: goal rungs 2, 3 on %d and %d DoFs, uniform rung 2 on %d (README 19995, 56619, 45375)"
          % (goal[1][0], goal[2][0], uniform[1][0]))
rotation = ["Target/Quantities=rotation_right_z", "Geometry/Parameters/n=4", "Target/Refinement=adaptive",
            "Target/Relative error=0.001", "Target/Maximum refinements=4", "Quantities/Rotations=right"]
proc, goal_rows, _ = ladder("cook_membrane_linear.prm", rotation)
check("rotation_right_z: rotation_right_z, one dual" in proc.stdout, "Cook rotation: the target has a dual")
goal = true_errors(goal_rows, "rotation_right_z", COOK_ROTATION)
if check(len(goal) == 5, "Cook rotation: five goal-oriented rungs"):
    print("  Cook rotation goal: %s" % goal)
    check(goal[4][1] < 3e-4 and goal[4][1] < goal[0][1] / 20,
          "Cook rotation rung 5: %.3g %% off on %d DoFs (rung 1 %.3g %%)" % (100 * goal[4][1], goal[4][0], 100 * goal[0][1]))
    readme_figure(100 * goal[4][1], "0.0175", "Cook rotation goal-oriented rung 5: true error %")
    check(goal[4][0] == 1810, "Cook rotation rung 5 on %d DoFs (README 1810)" % goal[4][0])
proc, _, summary = ladder("cook_membrane_linear.prm", ["Geometry/Parameters/n=8", "Quantities/Rotations=right",
                                                      "Quantities/Error estimates=true"])
if check(summary is not None, "Cook rotation with error estimates: ran, exit %d" % proc.returncode):
    q = summary["quantities"]
    effectivity = q["rotation_right_z_error_estimate_absolute"] / abs(q["rotation_right_z"] - COOK_ROTATION)
    check(0.5 <= effectivity <= 3, "Cook rotation, 8 x 8 Q2: effectivity %.3g" % effectivity)
    readme_figure(effectivity, "0.79", "Cook rotation, 8 x 8 Q2: effectivity")

HINGE = 9.0838
hinge = ["Target/Relative error=0.5", "Target/Refinement=adaptive", "Target/Maximum refinements=8",
         "Boundary conditions/Rotation=drive: degrees=40, center=l/2 0"]
proc, rows, summary = ladder(os.path.join("..", "flexure_hinge.prm"), hinge, linear_only=False)
fs = [r for r in rows if r["model"] == "finite strain"]
check(proc.returncode == 0 and len(fs) >= 2, "hinge at 40 degrees, adaptive: finite-strain rungs (exit %d)" % proc.returncode)
check(proc.stdout.count("(duals of the tangent at the converged state)") == len(fs) - 1 and
      "rotational_stiffness_drive (reaction), one dual" in proc.stdout,
      "hinge at 40 degrees: every finite-strain rung but the last refines by its reaction's dual")
if fs and summary is not None:
    error = abs(float(fs[-1]["rotational_stiffness_drive"]) - HINGE) / HINGE
    print("  hinge adaptive: %s" % [(int(r["dofs"]), r["rotational_stiffness_drive"]) for r in fs])
    check(error <= 0.005 and int(fs[-1]["dofs"]) <= 18700 / 2,
          "hinge at 40 degrees: stops %.3g %% off on %s DoFs (uniform: 18.7k)" % (100 * error, fs[-1]["dofs"]))
    readme_figure(100 * error, "0.135", "hinge at 40 degrees, adaptive: true error %")
    readme_figure(float(fs[-1]["dofs"]) / 1000, "9.04", "hinge at 40 degrees, adaptive: thousands of DoFs")
    readme_figure(100 * summary["quantities"]["rotational_stiffness_drive_error_estimate"], "0.17",
                  "hinge at 40 degrees, adaptive: estimate %")
finish()
