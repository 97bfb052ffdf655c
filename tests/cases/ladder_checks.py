#!/usr/bin/python3
"""The model ladder (Target/Relative error): Richardson estimates against true errors, the target
met against independent references, the linear/finite-strain decision, and singular quantities.

1. Effectivity (estimate / true error) between 0.5 and 3 at every rung whose estimate rests on an
   observed order, and the final value within the target of the reference:
   - 2D cantilever with the exact elasticity solution on its boundary (Timoshenko-Goodier), degree 1
     and degree 2 (reference: the exact tip deflection);
   - Cook's membrane, linear plane stress, degree 2 from 4 x 4 cells (reference 23.96 at (48, 52),
     FinEtools/literature; kept linear with Target/Allow finite strain = false);
   - a 3D bar in Saint-Venant torsion, its torsion constant J (a derived quantity) against the series.
2. A flexure hinge driven to 2 degrees stays linear; at 40 degrees the ladder moves to finite strain,
   says why (the measured rotation squared exceeds the target) and climbs finite-strain rungs until
   their own estimate meets the target. The elastica (a cantilever under a dead tip load, alpha = 1,
   tip rotation 28.6 degrees in the linear answer) climbs the same way; its effectivity is checked
   against the converged continuum and its final value against the Euler elastica.
3. The peak von Mises stress of Cook's membrane sits at a re-entrant corner: no converged value, so
   the ladder reports irregular convergence and no estimate, and exits with code 4 (target not met).
4. Adaptive refinement (Kelly's indicator, asked for: the default is goal-oriented, see
   goal_adaptivity_checks.py; hanging nodes) on Cook's membrane meets a 0.01 % target on a steady
   observed order, with a trustworthy estimate, on far fewer DoFs than uniform refinement, and a
   0.05 % target through the safety factor on an unsteady order.
5. Rung (a): a closed form with its own error bound answers a slender cantilever without FE, the
   true error within the bound; a stocky one climbs.
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
# Cook's membrane at (48, 52), converged, from FEniCSx (cases/verification/cook_reference_fenicsx.md).
COOK_REFERENCE = 23.96774


def ladder(case, sets):
    out = tempfile.mkdtemp(prefix="ladder-")
    cmd = ["mpirun", "-np", "2", solver_path(), case, "--set", "Output/Directory=" + out,
           "--set", "Output/Fields=false"] + sum([["--set", s] for s in sets], [])
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    summary = json.load(open(os.path.join(out, "summary.json"))) if os.path.exists(os.path.join(out, "summary.json")) else None
    rows = list(csv.DictReader(open(os.path.join(out, "ladder.csv")))) if os.path.exists(os.path.join(out, "ladder.csv")) else []
    subprocess.run(["rm", "-rf", out])
    return proc, summary, rows


def written(name, summary, rows):
    """A ladder run that wrote no summary.json or no ladder.csv fails here, rather than skipping the
    checks that read them."""
    return check(summary is not None and len(rows) > 0, "%s: summary.json and ladder.csv written (%d rungs)"
                 % (name, len(rows)))


def effectivities(name, rows, quantity, reference, target, readme=None, final_dofs=None):
    """readme: {rung: (true error %, estimate %, effectivity)} as the README's ladder table prints them,
    each asserted to 3 units of its last digit; final_dofs: the README's DoFs of the last rung."""
    if not check(len(rows) > 0 and ("estimate_" + quantity) in rows[0],
                 "%s: ladder.csv has rungs and the column estimate_%s" % (name, quantity)):
        return
    ok_all, rated = True, 0
    for r in rows:
        true = abs(float(r[quantity]) - reference) / abs(reference)
        est = r["estimate_" + quantity]
        line = "  %s rung %s: %s DoFs, value %.8g, true error %.3g %%" % (name, r["rung"], r["dofs"], float(r[quantity]), 100 * true)
        if int(r["rung"]) >= 3 and r.get("model", "") != "closed form":  # observed order from three rungs
            if not est:  # a rung with three rungs behind it and no estimate is a failure, not a skip
                line += ", NO estimate"
                ok_all = False
            else:
                eff = float(est) / true if true > 0 else float("inf")
                line += ", estimate %.3g %%, effectivity %.2f" % (100 * float(est), eff)
                ok_all = ok_all and 0.5 <= eff <= 3
                rated += 1
        print(line)
    check(rated > 0, "%s: %d rung(s) with an estimate to rate" % (name, rated))
    final = abs(float(rows[-1][quantity]) - reference) / abs(reference)
    check(ok_all, "%s: effectivity within 0.5-3 at every rung with an observed order" % name)
    for rung, figures in sorted((readme or {}).items()):
        r = [x for x in rows if int(x["rung"]) == rung]
        if not check(len(r) == 1 and r[0]["estimate_" + quantity] != "", "%s: rung %d with an estimate" % (name, rung)):
            continue
        true = abs(float(r[0][quantity]) - reference) / abs(reference)
        estimate = float(r[0]["estimate_" + quantity])
        for what, value, text in zip(("true error %", "estimate %", "effectivity"),
                                     (100 * true, 100 * estimate, estimate / true), figures):
            if text is not None:
                readme_figure(value, text, "%s rung %d: %s" % (name, rung, what))
    if final_dofs is not None:
        check(int(rows[-1]["dofs"]) == final_dofs, "%s: stops at %s DoFs (README %d)" % (name, rows[-1]["dofs"], final_dofs))
    check(final <= target, "%s: final value within the target of the reference (%.3g %% <= %.2g %%)" % (name, 100 * final, 100 * target))


exact = os.path.join(cases, "verification", "cantilever_2d_exact.prm")
for degree in (1, 2):
    proc, summary, rows = ladder(exact, ["Target/Relative error=0.5", "Geometry/Parameters/ny=1",
                                         "Discretization/Element degree=%d" % degree])
    check(proc.returncode == 0, "cantilever degree %d: ladder exit code %d" % (degree, proc.returncode))
    reference = [c for c in summary["comparisons"] if c["quantity"] == "displacement_tip_y"][0]["reference"]
    effectivities("cantilever Q%d" % degree, rows, "displacement_tip_y", reference, 0.005,
                  *({1: ({3: ("2.87", "4.32", "1.51"), 4: ("0.735", "0.836", "1.14"), 5: ("0.185", "0.192", "1.04")}, 2210),
                     2: ({3: ("0.00109", "0.00182", "1.68")}, 594)}[degree]))

# Saint-Venant torsion in 3D: the torsion constant J measured from the twist rate between two sections
# and the end torque (a derived quantity), against the series of the rectangle 6 x 1.
bar = os.path.join(cases, "verification", "torsion_bar.prm")
proc, summary, rows = ladder(bar, ["Target/Relative error=0.5", "Target/Quantities=J", "Geometry/Parameters/nx=30",
                                   "Geometry/Parameters/ny=6", "Geometry/Parameters/nz=1", "Target/Refinement=uniform"])
check(proc.returncode == 0, "torsion bar: ladder exit code %d" % proc.returncode)
if written("torsion bar", summary, rows):
    reference = [c for c in summary["comparisons"] if c["quantity"] == "J"][0]["reference"]
    effectivities("torsion bar J", rows, "J", reference, 0.005, {3: ("0.00964", "0.0102", "1.06")})
    check(abs(int(rows[-1]["dofs"]) - 319e3) <= 3e3, "torsion bar: stops at %s DoFs (README 319k)" % rows[-1]["dofs"])

cook = os.path.join(cases, "verification", "cook_membrane_linear.prm")
proc, summary, rows = ladder(cook, ["Target/Relative error=0.5", "Target/Quantities=displacement_mid_y",
                                    "Target/Allow finite strain=false", "Geometry/Parameters/n=4"])
check(proc.returncode == 0 and "keeps it linear" in proc.stdout, "Cook: stays linear on request, exit %d" % proc.returncode)
effectivities("Cook Q2", rows, "displacement_mid_y", 23.96, 0.005, {3: ("0.0442", "0.0391", "0.88")})

proc, summary, rows = ladder(cook, ["Target/Relative error=0.5", "Target/Quantities=max_von_mises",
                                    "Target/Allow finite strain=false", "Geometry/Parameters/n=2",
                                    "Target/Maximum refinements=3"])
check(proc.returncode == 4 and "irregular convergence" in proc.stdout and "NOT met" in proc.stdout,
      "Cook peak von Mises at the corner: irregular, no estimate, exit %d" % proc.returncode)
# README: "differences grow by 1.25 per refinement"
v = [float(r["max_von_mises"]) for r in rows]
check(len(v) == 4, "Cook peak von Mises: 4 rungs in ladder.csv (%d)" % len(v))
for i in range(2, len(v)):
    readme_figure((v[i] - v[i - 1]) / (v[i - 1] - v[i - 2]), "1.25", "Cook peak von Mises rung %d: growth of the differences" % (i + 1))

# Adaptive refinement (Kelly indicator, hanging nodes) on Cook's membrane: the reference is the
# converged value 23.96774 of another code, FEniCSx Q2 on n = 128, 256, 512 by Richardson
# (cases/verification/cook_reference_fenicsx.md; the literature's 23.96 agrees to its 4 digits). Adaptive rungs converge unevenly (observed orders 2.8,
# 6.2, 3.9): the ladder stops on a steady order (two successive orders within a factor 1.5), or on
# an unsteady one only with a safety factor of 10. At 0.01 % it must stop on a steady order with a
# trustworthy estimate, on far fewer DoFs than uniform refinement (132k for an estimate under
# 0.01 %); at 0.05 % the safety factor must still keep the true error within the target.
cook_adaptive = ["Target/Quantities=displacement_mid_y", "Target/Allow finite strain=false", "Geometry/Parameters/n=4",
                 "Target/Refinement=adaptive", "Target/Maximum refinements=10", "Target/Refinement indicator=kelly"]
for target in (0.01, 0.05):
    proc, summary, rows = ladder(cook, cook_adaptive + ["Target/Relative error=%g" % target])
    check(proc.returncode == 0 and rows and int(rows[-1]["adaptive_cycles"]) == len(rows) - 1,
          "Cook adaptive %g %%: met with %d rungs, exit %d" % (target, len(rows), proc.returncode))
    if not rows:
        continue
    for r in rows:
        v = float(r["displacement_mid_y"])
        print("  Cook adaptive rung %s: %s DoFs, value %.8f, true error %.3g %%, estimate %s" % (
            r["rung"], r["dofs"], v, 100 * abs(v - COOK_REFERENCE) / COOK_REFERENCE, r["estimate_displacement_mid_y"]))
    final = float(rows[-1]["displacement_mid_y"])
    true = abs(final - COOK_REFERENCE) / COOK_REFERENCE
    check(true <= target / 100, "Cook adaptive %g %%: final within the target of the converged value (%.3g %%)" % (target, 100 * true))
    if written("Cook adaptive %g %%" % target, summary, rows):  # the estimate the stop read (x 10 on an unsteady order)
        reported = summary["quantities"]["displacement_mid_y_error_estimate"]
        check(0.5 <= reported / true <= 3, "Cook adaptive %g %%: effectivity of the reported estimate %.2f"
              % (target, reported / true))
    if target == 0.01:
        eff = float(rows[-1]["estimate_displacement_mid_y"]) / true if true > 0 else float("inf")
        check(0.5 <= eff <= 3, "Cook adaptive: effectivity of the steady estimate it stopped on %.2f" % eff)
        check(float(rows[-1]["dofs"]) < 132098 / 4, "Cook adaptive: %s DoFs against 132098 uniform" % rows[-1]["dofs"])
        # README: stops at rung 8, 0.00103 / 0.000941 % (0.91), 12k DoFs
        check(len(rows) == 8, "Cook adaptive 0.01 %%: stops at rung %d (README 8)" % len(rows))
        readme_figure(true, "0.00103", "Cook adaptive 0.01 %: true error %", 100)
        readme_figure(float(rows[-1]["estimate_displacement_mid_y"]), "0.000941", "Cook adaptive 0.01 %: estimate %", 100)
        readme_figure(eff, "0.91", "Cook adaptive 0.01 %: effectivity")
        readme_figure(float(rows[-1]["dofs"]) / 1000, "12", "Cook adaptive 0.01 %: thousands of DoFs")
        # README: rung 3 unsteady, rung 4's order 6.2 refused as above Q2's
        # attainable 4.6 (issue 28's guard: its bare estimate had an effectivity of 0.16), rung 5
        # unsteady (6.2 then 3.9), rung 6 irregular.
        refused = re.findall(r"observed order ([0-9.]+) above the attainable 4\.6", proc.stdout)
        check(len(refused) == 1, "Cook adaptive 0.01 %%: one order refused as above Q2's attainable 4.6 (%s)" % refused)
        if refused:
            readme_figure(float(refused[0]), "6.2", "Cook adaptive 0.01 %: the refused order")
        check(rows[3]["estimate_displacement_mid_y"] == "", "Cook adaptive 0.01 %: rung 4 has no estimate (refused)")
        unsteady = re.findall(r"not steady yet \(([0-9.]+) then ([0-9.]+)\)", proc.stdout)
        check(len(unsteady) == 1, "Cook adaptive 0.01 %%: the log gives one unsteady pair (%s)" % unsteady)
        if unsteady:
            readme_figure(float(unsteady[0][1]), "3.9", "Cook adaptive 0.01 %: rung 5 observed order")
        for r, text in zip((rows[2], rows[4]), ("2.4", "0.17")):  # README: rungs 3 and 5 unsteady, effectivities
            v = float(r["displacement_mid_y"])
            readme_figure(float(r["estimate_displacement_mid_y"]) / (abs(v - COOK_REFERENCE) / COOK_REFERENCE), text,
                          "Cook adaptive rung %s: effectivity" % r["rung"])
    else:
        # README: stops at rung 5 by the factor 10 (rung 4's estimate refused), true 0.018 %,
        # reported 0.030 % (1.65)
        check(len(rows) == 5, "Cook adaptive 0.05 %%: stops at rung %d (README 5)" % len(rows))
        readme_figure(true, "0.018", "Cook adaptive 0.05 %: true error %", 100)
        if summary is not None:
            reported = summary["quantities"]["displacement_mid_y_error_estimate"]
            readme_figure(reported, "0.030", "Cook adaptive 0.05 %: reported estimate %", 100)
            readme_figure(reported / true, "1.65", "Cook adaptive 0.05 %: effectivity")

# Degree rungs (Target/Refinement = degree): degrees 2, 3, 4 on the starting mesh, the error
# extrapolated in the DoF count. One triple of degrees gives no steady order, so the ladder stops
# only when 8 x the estimate meets the target, and reports that bound (effectivities of the bare
# estimate: 0.32 on Cook, 0.23 on the torsion bar against the series, whose modelling share is
# ~3e-5; of the reported one 2.6 (2.57) and 1.8). Both stop at degree 4 on the starting mesh, without refining.
# The torsion bar runs with the default Target/Refinement = auto: degree rungs on 3D hexahedra.
for name, case, sets, quantity, reference in (
        ("Cook degree rungs", cook, ["Target/Allow finite strain=false", "Geometry/Parameters/n=4",
                                     "Target/Refinement=degree"], "displacement_mid_y", COOK_REFERENCE),
        ("torsion bar degree rungs (auto)", bar, ["Geometry/Parameters/nx=30", "Geometry/Parameters/ny=6",
                                                  "Geometry/Parameters/nz=1"], "J", None)):
    proc, summary, rows = ladder(case, sets + ["Target/Relative error=0.5", "Target/Quantities=" + quantity])
    check(proc.returncode == 0 and len(rows) == 3, "%s: met in %d rungs, exit %d" % (name, len(rows), proc.returncode))
    if not written(name, summary, rows):
        continue
    if reference is None:
        reference = [c for c in summary["comparisons"] if c["quantity"] == quantity][0]["reference"]
    check([r["degree"] for r in rows] == ["2", "3", "4"] and all(r["refinements"] == "0" for r in rows),
          "%s: degrees %s on the starting mesh" % (name, [r["degree"] for r in rows]))
    true = abs(float(rows[-1][quantity]) - reference) / abs(reference)
    estimate = float(rows[-1]["estimate_" + quantity])
    stop = float(rows[-1]["stop_estimate_" + quantity])
    reported = summary["quantities"][quantity + "_error_estimate"]
    check(true <= 0.005 and abs(stop - 8 * estimate) <= 1e-8 * stop and abs(reported - stop) <= 1e-8 * stop,
          "%s: true error %.3g %% within the target; the stop (and summary) estimate is 8 x the bare %.3g %%"
          % (name, 100 * true, 100 * estimate))
    check(0.5 <= stop / true <= 3, "%s: effectivity of the reported estimate %.3g %%: %.2f (bare %.2f)"
          % (name, 100 * stop, stop / true, estimate / true))
    # README (model ladder table): true / bare estimate (bare effectivity), reported 8 x (its effectivity), DoFs
    figures = {"Cook": ("0.11", "0.035", "0.32", "0.28", "2.57", 578),
               "torsion": ("0.0071", "0.0016", "0.23", "0.013", "1.82", 45375)}[name.split()[0]]
    for what, value, text in zip(("true error %", "bare estimate %", "bare effectivity", "reported estimate %",
                                  "reported effectivity"),
                                 (100 * true, 100 * estimate, estimate / true, 100 * stop, stop / true), figures):
        readme_figure(value, text, "%s: %s" % (name, what))
    check(int(rows[-1]["dofs"]) == figures[5], "%s: stops at %s DoFs (README %d)" % (name, rows[-1]["dofs"], figures[5]))
    # README: rungs 1 and 2, true error % / estimate % ("-": none on rung 1)
    first = {"Cook": ("0.53", "0.18", "0.11"), "torsion": ("1.44", "0.034", "0.45")}[name.split()[0]]
    readme_figure(abs(float(rows[0][quantity]) - reference) / abs(reference), first[0], "%s: rung 1 true error %%" % name, 100)
    readme_figure(abs(float(rows[1][quantity]) - reference) / abs(reference), first[1], "%s: rung 2 true error %%" % name, 100)
    readme_figure(float(rows[1]["estimate_" + quantity] or "nan"), first[2], "%s: rung 2 estimate %%" % name, 100)

hinge = os.path.join(cases, "flexure_hinge.prm")
for degrees, nonlinear in ((2, False), (40, True)):
    proc, summary, rows = ladder(hinge, ["Target/Relative error=0.5",
                                         "Boundary conditions/Rotation=drive: degrees=%d, center=l/2 0" % degrees])
    moved = any(r["model"] == "finite strain" for r in rows) and summary is not None and "load_steps" in summary["quantities"]
    said = [l.strip() for l in proc.stdout.splitlines() if l.strip().startswith("(c) largest rotation")]
    check(proc.returncode == 0 and moved == nonlinear,
          "flexure hinge at %d degrees: %s (%s)" % (degrees, "finite strain" if moved else "linear", said[0] if said else "?"))
    # README: theta 2.05 deg, theta^2 = 0.13 % (2 degrees); theta 55.5 deg (40 degrees)
    said_figures = re.findall(r"largest rotation ([0-9.]+) deg: geometric error ~theta\^2 = ([0-9.]+) %", proc.stdout)
    if check(len(said_figures) > 0, "flexure hinge at %d degrees: the log gives the largest rotation" % degrees):
        readme_figure(float(said_figures[0][0]), "55.5" if nonlinear else "2.05", "flexure hinge at %d degrees: theta (deg)" % degrees)
        if not nonlinear:
            readme_figure(float(said_figures[0][1]), "0.13", "flexure hinge at 2 degrees: theta^2 %")
    if written("flexure hinge at %d degrees" % degrees, summary, rows) and nonlinear:
        estimate = summary["quantities"].get("rotational_stiffness_drive_error_estimate")
        check(estimate is not None and estimate <= 0.005 and summary["settings"].get("ladder") == "target met",
              "flexure hinge at 40 degrees: finite-strain rungs end on their own estimate (%s)" % estimate)
        # README: finite-strain rungs 9.1692, 9.1258, 9.1032 (observed order 0.94), estimate 0.27 %,
        # stops at 18.7k DoFs (the converged ~9.092 it quotes is this code's own, so no true error here).
        fs = [r for r in rows if r["model"] == "finite strain"]
        check(len(fs) == 3, "flexure hinge at 40 degrees: %d finite-strain rungs (README 3)" % len(fs))
        for r, text in zip(fs, ("9.1692", "9.1258", "9.1032")):
            readme_figure(float(r["rotational_stiffness_drive"]), text, "flexure hinge rung %s" % r["rung"])
        if estimate is not None:
            readme_figure(estimate, "0.27", "flexure hinge at 40 degrees: estimate %", 100)
        readme_figure(summary["quantities"].get("rotational_stiffness_drive_observed_order", float("nan")), "0.94",
                      "flexure hinge at 40 degrees: observed order")
        readme_figure(float(rows[-1]["dofs"]) / 1000, "18.7", "flexure hinge at 40 degrees: thousands of DoFs")

# The elastica, alpha = 1, from 10 x 1 Q2 cells: linear rung 1 (rotation 28.6 deg) sends the climb
# to finite strain. Effectivity against the converged continuum (tip 30.174142 and shortening
# 5.6435944 at 5 refinements, 83k DoFs, changing by 5e-7 from 4 refinements); the Euler elastica
# (Bisshopp and Drucker: 30.17208, 5.64332) lies 7e-5 below the continuum (shear, thickness), far
# inside the target, so the final value must also be within the target of it.
elastica = os.path.join(cases, "verification", "elastica_tip_load.prm")
proc, summary, rows = ladder(elastica, ["Analysis=linear static", "Target/Relative error=0.5",
                                        "Geometry/Parameters/nx=10", "Geometry/Parameters/ny=1"])
check(proc.returncode == 0 and rows and rows[0]["model"] == "linear" and rows[-1]["model"] == "finite strain",
      "elastica: linear rung, then finite-strain rungs to the target (exit %d)" % proc.returncode)
said_figures = re.findall(r"largest rotation ([0-9.]+) deg", proc.stdout)
if check(len(said_figures) > 0, "elastica: the log gives the linear rung's largest rotation"):
    readme_figure(float(said_figures[0]), "28.6", "elastica: linear rung's theta (deg)")  # README: theta 28.6 deg
if written("elastica", summary, rows):
    fs_first = [r for r in rows if r["model"] == "finite strain"][:1]  # README: first finite-strain rung 1.58 % / -
    readme_figure(abs(float(fs_first[0]["displacement_tip_y"]) / 30.174142 - 1) if fs_first else float("nan"), "1.58",
                  "elastica: first finite-strain rung's true error %", 100)
    figures = {"displacement_tip_y": {3: ("0.129", "0.208", "1.61"), 4: ("0.0106", "0.0105", "1.00")},
               "tip_shortening": {3: ("0.239", "0.396", "1.65"), 4: ("0.019", "0.0191", "1.00")}}
    for quantity, converged in (("displacement_tip_y", 30.174142), ("tip_shortening", 5.6435944)):
        effectivities("elastica " + quantity, rows,
                      quantity, converged, 0.005, figures[quantity])
        closed = [c for c in summary["comparisons"] if c["quantity"] == quantity][0]
        check(abs(closed["relative_difference"]) <= 0.005,
              "elastica %s: final value within the target of the Euler elastica (%.2g)" % (quantity, closed["relative_difference"]))
        if quantity == "displacement_tip_y":  # README: final 3.7e-5 from the elastica
            readme_figure(abs(closed["relative_difference"]), "3.7e-5", "elastica: final value from the Euler elastica")

# Degree rungs in finite strain (Target/Refinement = degree; auto keeps finite strain uniform): the
# elastica climbs degrees 2, 3, 4 on the 10 x 1 mesh. The tip deflection converges exponentially in
# the degree, so 8 x the Richardson estimate is conservative here (the final true error ~1e-7 of
# the converged continuum): the bound must hold the true error and meet the target.
proc, summary, rows = ladder(elastica, ["Analysis=linear static", "Target/Relative error=0.5",
                                        "Geometry/Parameters/nx=10", "Geometry/Parameters/ny=1",
                                        "Target/Refinement=degree", "Target/Quantities=displacement_tip_y"])
fs_rows = [r for r in rows if r["model"] == "finite strain"]
check(proc.returncode == 0 and [r["degree"] for r in fs_rows] == ["2", "3", "4"],
      "elastica degree rungs: finite strain at degrees %s, exit %d" % ([r["degree"] for r in fs_rows], proc.returncode))
if written("elastica degree rungs", summary, fs_rows):
    true = abs(float(fs_rows[-1]["displacement_tip_y"]) / 30.174142 - 1)
    reported = summary["quantities"]["displacement_tip_y_error_estimate"]
    print("  elastica degree rungs: true error %.3g %%, reported %.3g %% (effectivity %.1f), %s DoFs"
          % (100 * true, 100 * reported, reported / true if true > 0 else float("inf"), fs_rows[-1]["dofs"]))
    check(true <= reported <= 0.005, "elastica degree rungs: true error <= reported estimate <= target")
    # README: 410 DoFs, true error 1.2e-7, reported 9.2e-7
    check(fs_rows[-1]["dofs"] == "410", "elastica degree rungs: %s DoFs (README 410)" % fs_rows[-1]["dofs"])
    readme_figure(true, "1.2e-7", "elastica degree rungs: true error")
    readme_figure(reported, "9.2e-7", "elastica degree rungs: reported estimate")

# Rung (a): a closed form whose own bound meets the target answers without any FE model. The 2D
# cantilever (plane stress, clamped, end load) at L/h = 40: Timoshenko's bound is 0.069 % (shear
# term against Timoshenko-Goodier, root restraint (h/L)^2, geometric term from the elastica). Its
# true error against the converged continuum from another code (FEniCSx Q3, ny = 8, 16, 32, Richardson:
# -1.28010, +-5e-6 from the clamp corners' slow convergence; cases/verification/cantilever_reference_fenicsx.md)
# must lie within the bound and the target. At L/h = 10 the smallest bound is 1.1 % > 0.5 %: it climbs.
cantilever = os.path.join(cases, "verification", "cantilever_2d.prm")
slender = ["Geometry/Parameters/L=400", "Target/Relative error=0.5", "Target/Quantities=mean_displacement_right_y"]
proc, summary, rows = ladder(cantilever, slender)
ok = proc.returncode == 0 and summary and len(rows) == 1 and rows[0]["model"] == "closed form"
check(ok, "slender cantilever: rung (a) answers by a closed form, no FE rung (exit %d, %d rungs)" % (proc.returncode, len(rows)))
if ok:
    value = summary["quantities"]["mean_displacement_right_y"]
    bound = summary["quantities"]["mean_displacement_right_y_error_estimate"]
    true = abs(value / -1.28010 - 1)
    print("  closed form %.8g, bound %.3g %%, true error %.3g %%" % (value, 100 * bound, 100 * true))
    check(true <= bound <= 0.005, "slender cantilever: true error <= bound <= target")
    readme_figure(bound, "0.069", "slender cantilever: bound %", 100)  # README: bound 0.069 %, true 0.041 %
    readme_figure(true, "0.041", "slender cantilever: true error %", 100)
proc, summary, rows = ladder(cantilever, slender + ["Target/Closed forms=false"])
check(proc.returncode == 0 and len(rows) >= 3 and rows[0]["model"] == "linear",
      "Target/Closed forms = false climbs FE rungs (%d)" % len(rows))
proc, summary, rows = ladder(cantilever, ["Target/Relative error=0.5", "Target/Quantities=mean_displacement_right_y"])
check(proc.returncode == 0 and len(rows) >= 3 and "bound" in proc.stdout and "> target" in proc.stdout,
      "stocky cantilever (L/h = 10): the bound misses the target, said, and the FE rungs climb")
closest = [float(b) for b in re.findall(r"bound ([0-9.]+) % > target", proc.stdout)]  # README: closest bound 1.1 %
check(len(closest) > 0, "stocky cantilever: the log gives the closed forms' bounds (%s)" % closest)
readme_figure(min(closest) if closest else float("nan"), "1.1", "stocky cantilever (L/h = 10): closest bound %")

finish()
