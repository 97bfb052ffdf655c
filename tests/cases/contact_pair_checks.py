#!/usr/bin/python3
"""Contact between boundaries of the part (Contact/Pairs, nonlinear static), checked against
references that do not come from the contact code: the uniform state of the contact patch test,
Hertz's closed form, the same contact solved against a rigid plane (Contact/Obstacles), the
equilibrium of the reactions, and the same run on other rank counts.

    contact_pair_checks.py patch | hertz | fork | pin | ranks | moving | inputs
"""
import math
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
cases = os.path.join(here, "..", "..", "cases")
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
sys.path.insert(0, here)
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish, readme_figure, unknown_mode  # noqa: E402
from contact_common import run_with_files, no_penetration, hertz_fit  # noqa: E402

PATCH = os.path.join(cases, "contact", "patch_blocks.prm")
TWO_CYLINDERS = os.path.join(cases, "contact", "hertz_two_cylinders.prm")
HERTZ = os.path.join(cases, "contact", "hertz_cylinder.prm")
FORK = os.path.join(cases, "contact", "fork_closing.prm")
PIN = os.path.join(cases, "contact", "flexure_hinge_pin.prm")
STOP = os.path.join(cases, "contact", "flexure_hinge_stop.prm")
H, DELTA = 0.5, 1e-6
SAME = "Material/Materials=*: steel, E=1000, nu=0.3"
SUPPORTS_3D = ("Boundary conditions/Displacement=base: y=0; lower_left: x=0; upper_left: x=0; "
               "lower_back: z=0; upper_back: z=0; top: y=-%g" % DELTA)


def patch(label, sets, np=2):
    """Runs the patch test; returns (summary quantities, the slave nodes' pressures)."""
    q, curve, nodes = run_with_files(PATCH, sets, np=np)
    pressures = [float(n["pressure"]) for n in nodes]
    held = sum(1 for n in nodes if n["obstacle"])
    check(held == len(nodes) and held > 0, "%s: all %d slave nodes held (%d)" % (label, len(nodes), held))
    mean = sum(pressures) / len(pressures)
    spread = (max(pressures) - min(pressures)) / mean
    print("%s: %d nodes, pressure %.10g, spread %.2e, Newton %s" %
          (label, len(nodes), mean, spread, [r["newton_iterations"] for r in curve]))
    force = q["contact_force_blocks_y"]  # on the slave block (the upper or, swapped, the lower)
    check(abs(abs(force) - abs(q["reaction_force_top_y"])) <= 1e-9 * abs(force),
          "%s: contact force %.10g balances the top's reaction %.10g" % (label, force, q["reaction_force_top_y"]))
    no_penetration(q, nodes, label)
    return q, mean, spread


mode = sys.argv[1] if len(sys.argv) > 1 else ""
if mode == "patch":
    # One material in both blocks: the uniform state is the exact answer at any strain, so every
    # node's pressure is the same to round-off (the displacements are 1e-6 of the coordinates: 1e-9
    # of the pressure is the floor), matching or not, Q1 and Q2, 2D and 3D, either side as slave.
    E, nu = 1000.0, 0.3
    plane_strain = DELTA / (2 * H * (1 - nu ** 2) / E)  # small strain, both blocks alike
    uniaxial = DELTA / (2 * H / E)  # 3D: z free at the front, x free at the right
    runs = [("2D Q1, 5 against 7 cells", [SAME], plane_strain),
            ("2D Q1, matching 5 and 5", [SAME, "Geometry/Parameters/nu=5"], plane_strain),
            ("2D Q2, 5 against 7 cells", [SAME, "Discretization/Element degree=2"], plane_strain),
            ("2D Q1, lower block as slave", [SAME, "Contact/Pairs=blocks: slave=lower_face, master=upper_face"],
             plane_strain),
            ("3D Q1, 5 x 3 against 7 x 4 cells", [SAME, "Model=3d", "Geometry/Parameters/depth=0.4", SUPPORTS_3D],
             uniaxial),
            ("3D Q1, matching", [SAME, "Model=3d", "Geometry/Parameters/depth=0.4", SUPPORTS_3D,
                                 "Geometry/Parameters/nu=5", "Geometry/Parameters/nzu=3"], uniaxial),
            ("3D Q2, 5 x 3 against 7 x 4 cells", [SAME, "Model=3d", "Geometry/Parameters/depth=0.4", SUPPORTS_3D,
                                                  "Discretization/Element degree=2"], uniaxial)]
    for label, sets, small_strain in runs:
        q, mean, spread = patch(label, sets)
        check(spread <= 1e-8, "%s: a uniform pressure passes across the contact (spread %.2e <= 1e-8)" % (label, spread))
        check(abs(mean / small_strain - 1) <= 1e-5, "%s: pressure %.10g = small-strain %.10g to 1e-5 (strain 2e-6)"
              % (label, mean, small_strain))
    # Two materials: the blocks' lateral strains differ, the contact slides, and at finite strain
    # the upper block's end overhangs the lower one by the difference (1.6e-7 here): the nodes
    # next to it depart from the uniform state by the order of the strain, no more, and ten times
    # less at a ten times smaller push (the small-strain limit is uniform).
    spreads = []
    for delta in (1e-6, 1e-7):
        sets = ["Boundary conditions/Displacement=base: y=0; lower_left: x=0; upper_left: x=0; top: y=-%g" % delta,
                "Contact/Penetration tolerance=1e-12"]
        spreads.append(patch("2D Q1, two materials, push %g" % delta, sets)[2])
    check(spreads[0] <= 2 * DELTA / H, "two materials: spread %.2e within the order of the strain %.1e"
          % (spreads[0], DELTA / H))
    check(spreads[1] <= 0.2 * spreads[0], "two materials: spread %.2e at a ten times smaller push (%.2e there)"
          % (spreads[1], spreads[0]))
    readme_figure(spreads[0], "2.5e-7", "two materials: spread at a push of 1e-6")
    readme_figure(spreads[1], "2.7e-8", "two materials: spread at a push of 1e-7")
elif mode == "hertz":
    # Two equal cylinders pressed together: by symmetry their contact stays on y = 0, the rigid
    # plane of hertz_cylinder.prm, so the pair must carry the obstacle run's force and pressures;
    # Hertz for two cylinders (R* = R/2, E* = E / (2 (1 - nu^2))) gives the same b and p0.
    E, nu, R = 1000.0, 0.3, 10.0
    q, curve, nodes = run_with_files(TWO_CYLINDERS)
    q_plane, curve_plane, _ = run_with_files(HERTZ)
    P = 2 * q["contact_force_cylinders_y"]
    b_h = math.sqrt(4 * P * (R / 2) / (math.pi * E / (2 * (1 - nu ** 2))))
    p0_h = 2 * P / (math.pi * b_h)
    b, p0, p_center, held = hertz_fit(nodes)
    print("two cylinders: P = %.8g (rigid plane %.8g), %d held nodes; b %.5f (Hertz %.5f, %+.2f %%), p0 %.4f, "
          "at x = 0 %.4f (Hertz %.4f: %+.2f %%, %+.2f %%); Newton %s (plane %s)" %
          (P, 2 * q_plane["contact_force_ground_y"], held, b, b_h, 100 * (b / b_h - 1), p0, p_center, p0_h,
           100 * (p0 / p0_h - 1), 100 * (p_center / p0_h - 1), [r["newton_iterations"] for r in curve],
           [r["newton_iterations"] for r in curve_plane]))
    # The two discs' meshes are mirror images (gmsh meshes each alike): the same force to 8 digits.
    check(abs(q["contact_force_cylinders_y"] / q_plane["contact_force_ground_y"] - 1) <= 1e-7,
          "the pair carries the rigid plane's force to 8 digits")
    for name, value, reference in (("half-width b", b, b_h), ("peak pressure p0 (fitted)", p0, p0_h),
                                   ("pressure at x = 0", p_center, p0_h)):
        check(abs(value / reference - 1) < 0.02, "%s within 2 %% of Hertz (%+.2f %%)" % (name, 100 * (value / reference - 1)))
    # The README's figures (Contact between boundaries), to 3 units of their last digit.
    for value, reference, figure, name in ((b, b_h, "-0.30", "b"), (p0, p0_h, "+0.24", "p0 fitted"),
                                           (p_center, p0_h, "+0.31", "p at x = 0")):
        readme_figure(value / reference - 1, figure, "two cylinders: %s against Hertz, %%" % name, scale=100)
    for side in ("top", "bottom"):
        check(abs(abs(q["reaction_force_%s_y" % side]) - P / 2) <= 1e-8 * P,
              "the %s's reaction %.10g balances the contact force %.10g" % (side, q["reaction_force_%s_y" % side], P / 2))
    check(abs(q["contact_force_cylinders_x"]) <= 1e-4 * P, "no tangential force (frictionless): %.2g" %
          q["contact_force_cylinders_x"])
    no_penetration(q, nodes, "two cylinders")
elif mode == "fork":
    # A one-piece fork closing onto itself: the tips' compliances without the contact (a tenth of
    # the load, one step: the linear range) give R = (F - g / (c - d)) / 2 and the lower tip's
    # deflection c R + d (F - R), to the 1 % the tip's load spreading and finite strain allow.
    F, g = 0.02, 0.32
    free, _, _ = run_with_files(FORK, ["Contact/Pairs=", "Finite strain/Initial step=1",
                                       "Loads/Traction=upper_tip: 0 -%g/h" % (F / 10)])
    c = -free["mean_displacement_upper_tip_y"] / (F / 10)
    d = -free["mean_displacement_lower_tip_y"] / (F / 10)
    q, curve, nodes = run_with_files(FORK)
    R = -q["contact_force_slot_y"]  # on the lower prong (the slave): downwards
    R_expected = (F - g / (c - d)) / 2
    lower = -q["mean_displacement_lower_tip_y"]
    lower_expected = c * R_expected + d * (F - R_expected)
    print("fork: c %.5g, d %.5g; R %.7g (compliances %.7g, %+.3f %%; beam theory %.4g), lower tip %.6g (%.6g, %+.3f %%); "
          "Newton %d over %d steps" % (c, d, R, R_expected, 100 * (R / R_expected - 1), (F - 3 * 1000 / 12 / 20 ** 3 * g) / 2,
                                       lower, lower_expected, 100 * (lower / lower_expected - 1),
                                       sum(int(r["newton_iterations"]) for r in curve), len(curve)))
    check(abs(R / R_expected - 1) <= 0.01, "contact force within 1 % of the compliances' prediction")
    readme_figure(R / R_expected - 1, "+0.007", "fork: contact force against the compliances, %", scale=100)
    readme_figure(lower / lower_expected - 1, "-0.043", "fork: lower tip against the compliances, %", scale=100)
    check(abs(lower / lower_expected - 1) <= 0.01, "lower tip deflection within 1 % of the prediction")
    check(abs(q["reaction_force_root_y"] - F) <= 1e-8 * F, "the root carries the load %.10g" % q["reaction_force_root_y"])
    no_penetration(q, nodes, "fork")
elif mode == "pin":
    # A travel stop drawn in the geometry: the steel pin meshed with the hinge (Contact/Pairs)
    # against the rigid circle of Contact/Obstacles, where the link's face is resolved finely
    # (nt = 8: its nodes 0.6 apart; at the case's nt = 2 they are 2 apart and the rigid pin sinks
    # between them, 0.25 degrees further). Equilibrium: base and bore carry what the moment puts
    # on the link (Newton stops on its correction here, at a residual of 4e-4 of the forces).
    q, curve, nodes = run_with_files(PIN)
    q_rigid, _, _ = run_with_files(STOP, ["Geometry/Parameters/nt=8"])
    angle, rigid = q["link_angle_deg"], q_rigid["link_angle_deg"]
    print("pin: %.4f degrees at the full moment (rigid circle, nt = 8: %.4f); pin force %.6g %.6g; Newton %d over %d steps"
          % (angle, rigid, q["contact_force_pin_x"], q["contact_force_pin_y"],
             sum(int(r["newton_iterations"]) for r in curve), len(curve)))
    check(abs(angle - rigid) <= 0.05, "the link stops within 0.05 degrees of the rigid circle's angle (%.4f)" % (angle - rigid))
    check(10 < angle < 10.5, "past the 10 degrees where the rigid link would touch (%.4f)" % angle)
    force = math.hypot(q["contact_force_pin_x"], q["contact_force_pin_y"])
    for axis in ("x", "y"):
        imbalance = q["reaction_force_base_%s" % axis] + q["reaction_force_pin_bore_%s" % axis]
        check(abs(imbalance) <= 1e-3 * force, "base + bore in %s: %.3g (1e-3 of the pin force %.4g)" % (axis, imbalance, force))
    readme_figure(angle, "10.25", "pin: angle at the full moment, degrees")
    readme_figure(rigid, "10.27", "rigid circle, nt = 8: angle at the full moment, degrees")
    no_penetration(q, nodes, "pin")
elif mode == "ranks":
    # The same answers on 1, 2 and 3 ranks (the master surface is known on every rank).
    for label, case, sets, key in (("3D patch", PATCH, [SAME, "Model=3d", "Geometry/Parameters/depth=0.4", SUPPORTS_3D],
                                    "contact_force_blocks_y"),
                                   ("two cylinders", TWO_CYLINDERS, ["Geometry/Parameters/nb=10"],
                                    "contact_force_cylinders_y")):
        runs = {np: run_with_files(case, sets, np=np)[0] for np in (1, 2, 3)}
        for np in (2, 3):
            for name in (key, "contact_nodes_" + key.split("_")[2], "reaction_force_top_y"):
                a, b = runs[1][name], runs[np][name]
                check(abs(a - b) <= 1e-9 * abs(a), "%s: %s on %d ranks %.12g = on 1 rank %.12g" % (label, name, np, b, a))
elif mode == "moving":
    # A stop drawn in the geometry and moved by a prescribed motion: the lower block's face, driven
    # up by Boundary conditions/Displacement, is the master surface (a rigid obstacle of the shape
    # gmsh draws); the upper block, held at its top, is squeezed by 1e-6 between them. Every slave
    # node carries the upper block's uniaxial plane-strain pressure, on meshes of 40 against 56
    # cells, the same on 1 and 3 ranks.
    E_upper, nu_upper = 400.0, 0.1
    expected = DELTA / (H * (1 - nu_upper ** 2) / E_upper)
    sets = ["Geometry/Parameters/nl=40", "Geometry/Parameters/nu=56", "Geometry/Parameters/ny=12",
            "Boundary conditions/Displacement=base: y=0; lower_left: x=0; upper_left: x=0; top: y=0; "
            "lower_face: y=%g" % DELTA]
    runs = {}
    for np in (1, 3):
        q, curve, nodes = run_with_files(PATCH, sets, np=np)
        pressures = [float(n["pressure"]) for n in nodes]
        held = sum(1 for n in nodes if n["obstacle"])
        mean = sum(pressures) / len(pressures)
        spread = (max(pressures) - min(pressures)) / mean
        label = "driven master face, %d rank%s" % (np, "s" if np > 1 else "")
        print("%s: %d nodes, pressure %.10g, spread %.2e, Newton %s" %
              (label, len(nodes), mean, spread, [r["newton_iterations"] for r in curve]))
        check(held == len(nodes) == 57, "%s: all %d slave nodes held (%d)" % (label, len(nodes), held))
        check(spread <= 1e-8, "%s: a uniform pressure (spread %.2e <= 1e-8)" % (label, spread))
        check(abs(mean / expected - 1) <= 1e-5, "%s: pressure %.10g = the upper block's small-strain %.10g to 1e-5"
              % (label, mean, expected))
        force = q["contact_force_blocks_y"]
        check(abs(force + q["reaction_force_top_y"]) <= 1e-9 * abs(force),
              "%s: contact force %.10g balances the top's reaction" % (label, force))
        no_penetration(q, nodes, label)
        runs[np] = q
    for name in ("contact_force_blocks_y", "reaction_force_top_y", "reaction_force_base_y"):
        a, b = runs[1][name], runs[3][name]
        check(abs(a - b) <= 1e-9 * abs(a), "driven master face: %s on 3 ranks %.12g = on 1 rank %.12g" % (name, b, a))
elif mode == "inputs":
    # Bad pairs: one clear error naming the case file and the parameter, exit 2, no output.
    bad = (("Contact/Pairs=blocks: slave=upper_face, master=nowhere", "nowhere"),
           ("Contact/Pairs=blocks: slave=upper_face", "master="),
           ("Contact/Pairs=blocks: slave=upper_face, master=upper_face", "both slave and master"),
           ("Contact/Pairs=blocks: slave=upper_face, master=lower_face, friction=0.3", "friction"),
           ("Contact/Pairs=a: slave=upper_face, master=lower_face; a: slave=top, master=base", "given twice"),
           ("Contact/Pairs=a: slave=upper_face, master=lower_face; b: slave=lower_face, master=upper_face",
            "never be another pair's master"),
           ("Analysis=linear static", "nonlinear static"))
    for setting, expected in bad:
        out = tempfile.mkdtemp(prefix="compliant-pair-input-")
        os.rmdir(out)
        proc = subprocess.run(["mpirun", "-np", "2", solver_path(), PATCH, "--set", setting,
                               "--set", "Output/Directory=" + out], capture_output=True, text=True, env=mpi_env())
        message = proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else ""
        check(proc.returncode == 2 and "Contact" in proc.stderr and expected in proc.stderr and "patch_blocks.prm" in proc.stderr,
              "'%s': exit %d, '%s'" % (setting, proc.returncode, message[:200]))
        check(not os.path.exists(out), "'%s': no output directory" % setting)
else:
    unknown_mode(mode, ("patch", "hertz", "fork", "pin", "ranks", "moving", "inputs"))
finish()
