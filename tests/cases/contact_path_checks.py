#!/usr/bin/python3
"""Contact on an arc-length path (Finite strain/Path = arc length with Contact/Obstacles or
Contact/Pairs), checked against paths that do not come from it: the same equilibrium reached by a
displacement drive in load steps, the path of the same structure without the stop, and load
steps where they get through.

    contact_path_checks.py arch | load_steps
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
cases = os.path.join(here, "..", "..", "cases")
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
sys.path.insert(0, here)
from case_checks import check, finish, readme_figure, unknown_mode  # noqa: E402
from contact_common import run_with_files, no_penetration  # noqa: E402

ARCH = os.path.join(cases, "contact", "arch_snap_stop.prm")
STOP = os.path.join(cases, "contact", "flexure_hinge_stop.prm")
FORK = os.path.join(cases, "contact", "fork_closing.prm")
STOP_3D = os.path.join(cases, "contact", "cantilever_3d_stop.prm")
NO_STOP = ["Contact/Obstacles=", "Contact/Boundaries="]


def close(a, b, tol):
    return abs(a - b) <= tol * max(abs(a), abs(b), 1e-300)


mode = sys.argv[1] if len(sys.argv) > 1 else ""
if mode == "arch":
    q, curve, nodes = run_with_files(ARCH)
    print("arch with the stop: %d steps, %d Newton, limit points %s" %
          (q["load_steps"], q["newton_iterations"],
           [q.get("limit_point_%d" % k) for k in range(1, int(q.get("limit_points", 0)) + 1)]))
    check(q["load_factor"] == 1, "the path reaches load factor 1 (%.9g)" % q["load_factor"])
    # The arch alone follows the same path until its crown reaches the stop: every step of the free
    # arch above the stop is a step of the arch with it.
    free_q, free_curve, _ = run_with_files(ARCH, NO_STOP)
    touch = -4.0  # the crown's underside (y = 4.5) meets the stop's top (y = 0.5)
    above_stop = next(k for k, r in enumerate(free_curve) if float(r["displacement_crown_y"]) < touch)
    first = next(k for k, r in enumerate(curve) if int(r["contact_active_nodes"]) > 0)
    worst = max(max(abs(float(a["load_factor"]) - float(b["load_factor"])),
                    abs(float(a["displacement_crown_y"]) - float(b["displacement_crown_y"])))
                for a, b in zip(curve[:above_stop], free_curve[:above_stop]))
    check(above_stop > 10 and first >= above_stop and worst <= 1e-9,
          "the free arch's %d steps above the stop are the first steps with it (largest difference %.2g)"
          % (above_stop, worst))
    # The free arch's crown passes the stop falling: there the load factor turns (a limit point
    # at the kink) and rises along the contact branch with the contact force.
    above, below = free_curve[above_stop - 1], free_curve[above_stop]
    check(float(below["load_factor"]) < float(above["load_factor"]) and int(above["unstable_modes"]) > 0,
          "the free arch passes the stop falling and unstable (load factor %.6g then %.6g, %s negative "
          "eigenvalues): the stop catches a snap-through" % (float(above["load_factor"]),
                                                            float(below["load_factor"]), above["unstable_modes"]))
    rising = all(float(curve[k + 1]["load_factor"]) > float(curve[k]["load_factor"]) and
                 float(curve[k + 1]["contact_force_stop_y"]) > float(curve[k]["contact_force_stop_y"])
                 for k in range(first, len(curve) - 1))
    check(rising, "on the contact branch the load factor and the contact force rise at every step (%d steps)"
          % (len(curve) - first))
    kink = [q["limit_point_%d" % k] for k in range(1, int(q.get("limit_points", 0)) + 1)]
    bracket = (float(curve[first - 1]["load_factor"]), float(curve[first]["load_factor"]))
    # (The cubic through the two steps either side locates a kink a little below both: 1e-3 of slack.)
    check(any(min(bracket) - 1e-3 <= k <= max(bracket) for k in kink) and len(kink) == 2,
          "two limit points, the upper one of the free arch (%.6g = %.6g) and the kink at the stop (%s)"
          % (kink[0], free_q.get("limit_point_1", float("nan")), kink[1:]))
    check(close(kink[0], free_q["limit_point_1"], 1e-9), "the upper limit point is the free arch's")
    # The stop meets the crown on the unstable branch (2 negative eigenvalues) and holds its
    # symmetric snap: one remains, the arch's sideways mode, which a round stop does not hold.
    check(int(curve[first - 1]["unstable_modes"]) == 2 and int(curve[-1]["unstable_modes"]) == 1,
          "negative eigenvalues %s before contact, %s at the end" % (curve[first - 1]["unstable_modes"],
                                                                    curve[-1]["unstable_modes"]))
    # Equilibrium at the end: the crown's force (1) = the stop + both clamps.
    total = q["contact_force_stop_y"] + q["reaction_force_left_y"] + q["reaction_force_right_y"]
    check(abs(total - 1) <= 1e-8, "stop %.9g + clamps %.9g + %.9g = %.12g, the crown's force 1"
          % (q["contact_force_stop_y"], q["reaction_force_left_y"], q["reaction_force_right_y"], total))
    no_penetration(q, nodes, "arch")
    # The same state by another path: the crown driven down to the arc-length end's displacement
    # in load steps (through both limit points and onto the stop), where the drive's reaction is
    # the load.
    drive = q["rigid_displacement_apex_y"]
    d_q, _, d_nodes = run_with_files(ARCH, ["Finite strain/Path=load steps", "Boundary conditions/Rigid=",
                                            "Boundary conditions/Displacement=apex: x=0, y=%.17g" % drive])
    # (Both converge to 1e-9 of the force scale; the drive is read to 17 digits.)
    check(close(-d_q["reaction_force_apex_y"], 1.0, 1e-8),
          "driven to the crown displacement %.12g: the drive's reaction %.12g equals the load 1 (to 1e-8)"
          % (drive, -d_q["reaction_force_apex_y"]))
    for name in ("contact_force_stop_y", "reaction_force_left_y", "strain_energy", "displacement_crown_y"):
        check(close(d_q[name], q[name], 1e-8), "%s: displacement drive %.12g, arc length %.12g (to 1e-8)"
              % (name, d_q[name], q[name]))
    readme_figure(q["contact_force_stop_y"], "0.9065", "the stop's force at load factor 1")
    readme_figure(q["reaction_force_left_y"], "0.0467", "each clamp's force at load factor 1")
    readme_figure(kink[0], "0.14862", "the upper limit point")
    readme_figure(kink[1], "0.0941", "the load factor where the crown meets the stop")
elif mode == "load_steps":
    # Where load steps get through (no limit point), arc length ends on the same state: a hinge
    # closing onto a rigid pin (Contact/Obstacles) and a fork closing onto itself (Contact/Pairs).
    # And in 3D, a cantilever pressed onto a cylinder by a tip traction (its own case drives the
    # tip's displacement); its load steps cut back twice, which used to start again from the
    # nodes the failed Newton had held and inverted an element at every step size.
    traction = ["Boundary conditions/Displacement=", "Loads/Traction=right: 0 -600 0"]
    for case, sets, names in (
            (STOP, [], ("contact_force_pin_x", "contact_force_pin_y", "rigid_rotation_drive_z")),
            (FORK, [], ("contact_force_slot_y", "mean_displacement_upper_tip_y", "mean_displacement_lower_tip_y")),
            (STOP_3D, traction, ("contact_force_stop_x", "contact_force_stop_y", "reaction_force_left_y"))):
        label = os.path.basename(case)
        steps, _, _ = run_with_files(case, sets)
        arc, _, arc_nodes = run_with_files(case, sets + ["Finite strain/Path=arc length"])
        print("%s: load steps %d steps, %d Newton; arc length %d steps, %d Newton" %
              (label, steps["load_steps"], steps["newton_iterations"], arc["load_steps"], arc["newton_iterations"]))
        check(arc["load_factor"] == 1 and arc["contact_active_nodes"] > 0,
              "%s: arc length reaches load factor 1 with %d nodes in contact" % (label, arc["contact_active_nodes"]))
        for name in names:
            check(close(arc[name], steps[name], 1e-6), "%s: %s by arc length %.10g, by load steps %.10g (to 1e-6)"
                  % (label, name, arc[name], steps[name]))
        no_penetration(arc, arc_nodes, label + " (arc length)")
else:
    unknown_mode(mode, ("arch", "load_steps"))
finish()
