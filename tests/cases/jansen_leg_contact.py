#!/usr/bin/python3
"""The Strandbeest leg standing on the ground (cases/jansen/leg_ground_contact.prm: nonlinear
static, pins at finite strain, the foot on a rigid plane that rises under it), checked against
references that do not come from the contact code: the statics of ideal pins for the contact
force the run finds (cases/jansen/leg_statics.py; the leg with its crank held is statically
determinate), the geometry of the foot, equilibrium, and the same run on other rank counts.

    jansen_leg_contact.py statics | ranks
"""
import json
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
cases = os.path.join(here, "..", "..", "cases")
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(cases, "jansen"))
from case_checks import check, finish, readme_figure, unknown_mode  # noqa: E402
from contact_common import run_with_files, no_penetration  # noqa: E402
import leg_statics  # noqa: E402

CASE = os.path.join(cases, "jansen", "leg_ground_contact.prm")
STATICS = os.path.join(cases, "jansen", "leg_statics.py")
THETA2 = 37.2089
GROUND = -434.975948800  # the case's ground level: the foot's lowest point y_H - 15


def lift(value):
    return "Contact/Obstacles=ground: plane, point=0 %.9f, normal=0 1, motion=0 %g" % (GROUND, value)


def joint_forces_against_statics(q, label, tolerance):
    """The pins' forces on the links against the ideal-pin statics of the leg loaded by the
    contact force along its line of action (x from the contact moment about E, the origin)."""
    force = q["contact_force_ground_y"]
    x = q["contact_moment_ground_z"] / force
    out = tempfile.mkdtemp(prefix="compliant-leg-contact-")
    try:
        summary = os.path.join(out, "summary.json")
        with open(summary, "w") as f:
            json.dump({"quantities": q}, f)
        proc = subprocess.run([sys.executable, STATICS, "--theta2", str(THETA2), "--load", "0", repr(force),
                               "--load-point", repr(x), repr(GROUND), "--summary", summary,
                               "--tolerance", str(tolerance)], capture_output=True, text=True)
    finally:
        subprocess.run(["rm", "-rf", out])
    worst = [line for line in proc.stdout.splitlines() if line.startswith("largest joint-force")]
    print("\n".join(proc.stdout.splitlines()[-4:]))
    check(proc.returncode == 0, "%s: contact force %.6g N at x = %.4f; the joint forces are the ideal pins' "
          "(%s)" % (label, force, x, worst[0] if worst else proc.stderr.strip()[-300:]))
    return force, x


mode = sys.argv[1] if len(sys.argv) > 1 else ""
if mode == "statics":
    q, curve, nodes = run_with_files(CASE)
    force, x = joint_forces_against_statics(q, "the leg on the ground (0.0126 mm lift)", 5e-4)
    readme_figure(force, "500.7", "the ground's force on the foot")
    # Frictionless flat ground: the force is vertical; the held node is the round end's lowest.
    check(abs(q["contact_force_ground_x"]) <= 1e-9 * force, "the ground's force is vertical (x: %.3g)"
          % q["contact_force_ground_x"])
    held = [n for n in nodes if n["obstacle"]]
    lowest = min(nodes, key=lambda n: float(n["reference_y"]))
    check(len(held) >= 1 and lowest in held, "the foot stands on its lowest node (%d held, the lowest at x = %s)"
          % (len(held), lowest["reference_x"]))
    H = leg_statics.joints(THETA2)["H"]
    check(abs(x - H[0]) <= 0.5, "the line of action passes %.3f mm from H (within half a cell's node spacing on "
          "the round end, 0.5)" % (x - H[0]))
    # The links in equilibrium: the ground, the motor at A and the ground pivot E.
    for c in "xy":
        total = sum(q["%s_%s" % (k, c)] for k in ("contact_force_ground", "reaction_force_eye_AB_A",
                                                  "reaction_force_eye_CDE_E", "reaction_force_eye_EG_E"))
        check(abs(total) <= 1e-8 * force, "%s: ground + motor + pivot E = %.3g (to 1e-8 of the force)" % (c, total))
    no_penetration(q, nodes, "leg")
    # At 1/70 of the lift the deformed geometry's share (the statics are of the reference pose)
    # falls with the load, to the round-off of the linear linkage analysis' own check.
    small, _, _ = run_with_files(CASE, [lift(0.00068)])
    joint_forces_against_statics(small, "the same leg at a 0.00068 mm lift", 1e-5)
elif mode == "ranks":
    runs = {np: run_with_files(CASE, np=np)[0] for np in (1, 2, 3)}
    for np in (1, 3):
        for name in ("contact_force_ground_y", "contact_moment_ground_z", "reaction_force_eye_CDE_E_x",
                     "reaction_force_eye_FGH_G_y", "mean_displacement_foot_y"):
            a, b = runs[2][name], runs[np][name]
            check(abs(a - b) <= 1e-9 * abs(a), "%s on %d ranks %.12g = on 2 ranks %.12g" % (name, np, b, a))
else:
    unknown_mode(mode, ("statics", "ranks"))
finish()
