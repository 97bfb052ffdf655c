#!/usr/bin/python3
"""CalculiX (Debian's calculix-ccx 2.20) on cases/benchmarks/flexure_finite_strain.prm, the peer of
fenicsx_flexure_finite_strain.py: the TPU strip [0, 20] x [-2.5, 2.5] x [-0.5, 0.5] mm (Semiflex,
E = 89.5 MPa, nu = 0.48) on 20N x 4N x N cells of 20-node hexahedra (C3D20R by default: reduced
2 x 2 x 2 integration; C3D20: 3 x 3 x 3 as ours), NLGEOM, clamped at x = 0, the end x = 20 turned
rigidly by 45 degrees about the axis (0, 1, 0) through (20, 2.5, 0.5).

Law (--law): `neo-hooke` is CalculiX's *HYPERELASTIC, NEO HOOKE, U = C10 (I1bar - 3) + (J - 1)^2 / D1
with C10 = mu/2, D1 = 2/K: the same small-strain mu and K as ours, W = mu/2 (I1 - 3) - mu ln J +
lambda/2 (ln J)^2, but a different law at finite strain (isochoric I1bar, volumetric (J - 1)^2).
`isochoric` is *HYPERELASTIC, ARRUDA-BOYCE with lambda_m = 1e4 and D = 2/K, which is
mu/2 (I1bar - 3) + K/4 (J^2 - 1 - 2 ln J) up to terms of 1/lambda_m^2 = 1e-8: exactly our law
"neo-Hookean isochoric", to tell the law's share of a difference from the element's.

Load (--load): `rigid` ties the end face to *RIGID BODY (a nonlinear MPC, exact finite rotation)
whose rotation node turns 45 degrees about y, so the angle is ramped as ours; that node's reaction
is a check on M_y. `boundary` prescribes each end node's final displacement R (X - c) + c - X by
*BOUNDARY, ramped linearly (a different path, the same end state: the law is elastic). Either way
the QoI M_y is summed from the end nodes' forces (RF) about the centre at the deformed positions
X + U, as ours and FEniCSx do (the two agree to 1e-7 at N = 1, 2: ccx prints 7 digits).

Increments (--steps): `ours` is our step control's rule (first step 0.1, growth 1.5, at most 0.25)
in CalculiX's automatic incrementation, which takes 0.1, 0.2, 0.35, 0.575, 0.825, 1 (ours 0.1, 0.25,
0.475, 0.725, 0.975, 1: CalculiX grows an increment only after two); `auto` is CalculiX's own
incrementation from 0.1. Equilibrium (--tolerance): `tight` asks the largest residual below 1e-8 of
the average nodal force, so that the answer is converged like ours (1e-9) and FEniCSx's; `default`
is CalculiX's 0.005. Two threads (OMP_NUM_THREADS, CCX_NPROC_EQUATION_SOLVER).

Prints one JSON line: DoFs, qoi (= M_y), both moments, u_z at (10, 2.5, 0.5), the load factors of
the increments and the Newton iterations from the .sta file, wall time of the ccx process, peak memory.
--grade G: the cells along x graded toward both ends, the longest G times the shortest, as
meshes/graded_layers.geo grades ours (`Geometry/Parameters/grade_x`, `graded_ends = 0`).
Run: calculix_flexure_finite_strain.py N WORK [--element C3D20R|C3D20] [--law neo-hooke|isochoric]
     [--load rigid|boundary] [--steps ours|auto] [--tolerance tight|default] [--grade G] [--deck-only]"""
import argparse
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calculix_common import Hex20Grid, graded, run_ccx, uniform  # noqa: E402

E, NU = 89.5, 0.48  # semiflex in mm-N-MPa (solver/fe/materials/library.dat)
MU, BULK = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))
ANGLE, CENTRE = math.radians(45.0), (20.0, 2.5, 0.5)
MID = (10.0, 2.5, 0.5)


def arguments():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("n", type=int, help="level: 20N x 4N x N cells")
    p.add_argument("work", help="directory for the deck and ccx's output")
    p.add_argument("--element", default="C3D20R", choices=["C3D20R", "C3D20"])
    p.add_argument("--law", default="neo-hooke", choices=["neo-hooke", "isochoric"])
    p.add_argument("--load", default="rigid", choices=["rigid", "boundary"])
    p.add_argument("--steps", default="ours", choices=["ours", "auto"])
    p.add_argument("--tolerance", default="tight", choices=["tight", "default"])
    p.add_argument("--grade", type=float, default=1.0, help="cells along x graded toward both ends (1: uniform)")
    p.add_argument("--deck-only", action="store_true", help="write WORK/job.inp, do not run ccx")
    return p.parse_args()


def material(law):
    """The hyperelastic card: both laws have the small-strain mu and K of (E, nu)."""
    if law == "neo-hooke":
        card = ["*HYPERELASTIC, NEO HOOKE", "%.10g, %.10g" % (MU / 2, 2 / BULK)]
    else:
        card = ["*HYPERELASTIC, ARRUDA-BOYCE", "%.10g, 1.e4, %.10g" % (MU, 2 / BULK)]
    return ["*MATERIAL, NAME=TPU"] + card + ["*SOLID SECTION, ELSET=EALL, MATERIAL=TPU"]


def turned(x, z, theta):
    """Displacement (ux, uz) of the point (x, z) turned rigidly by theta about y through CENTRE."""
    dx, dz = x - CENTRE[0], z - CENTRE[2]
    return (math.cos(theta) * dx + math.sin(theta) * dz - dx, -math.sin(theta) * dx + math.cos(theta) * dz - dz)


def node_sets(mesh, load):
    """Node sets FIX (x = 0), END (x = 20), MID; with the rigid load its reference and rotation nodes
    (new nodes at the centre, in no element) and the *RIGID BODY card. Returns (cards, ref, rot)."""
    end = mesh.nodes_where(0, 2 * mesh.nx)
    mid = [nid for nid, ijk in mesh.used.items() if math.dist(mesh.coordinates(*ijk), MID) < 1e-9]
    cards = ["*NSET, NSET=FIX"] + ["%d," % i for i in mesh.nodes_where(0, 0)]
    cards += ["*NSET, NSET=END"] + ["%d," % i for i in end] + ["*NSET, NSET=MID", "%d," % mid[0]]
    ref = rot = None
    if load == "rigid":
        ref, rot = max(mesh.used) + 1, max(mesh.used) + 2
        cards += ["*NODE"] + ["%d, %.12g, %.12g, %.12g" % ((i,) + CENTRE) for i in (ref, rot)]
        cards += ["*NSET, NSET=PILOT", "%d," % ref, "%d," % rot,
                  "*RIGID BODY, NSET=END, REF NODE=%d, ROT NODE=%d" % (ref, rot)]
    return cards, ref, rot


def boundary(mesh, load, ref, rot):
    """The clamp and the end turned by 45 degrees (final values; the step ramps them from 0)."""
    cards = ["*BOUNDARY", "FIX, 1, 3"]
    if load == "rigid":
        return cards + ["%d, 1, 3, 0." % ref, "%d, 1, 1, 0." % rot, "%d, 2, 2, %.10g" % (rot, ANGLE),
                        "%d, 3, 3, 0." % rot]
    for nid in mesh.nodes_where(0, 2 * mesh.nx):
        x, _, z = mesh.coordinates(*mesh.used[nid])
        ux, uz = turned(x, z, ANGLE)  # %.10g: ccx reads 20 characters
        cards += ["%d, 1, 1, %.10g" % (nid, ux), "%d, 2, 2, 0." % nid, "%d, 3, 3, %.10g" % (nid, uz)]
    return cards


def static(steps, tolerance):
    """*STEP to *STATIC and the convergence controls. `ours`: first increment 0.1, each next one 1.5
    times the last (I_G = 99: whatever the iterations), at most 0.25, the last one cut to end at 1:
    our step control's rule, so 0.1, 0.25, 0.475, 0.725, 0.975, 1. (Fixed increments through an
    *AMPLITUDE or one *STEP per factor diverge: CalculiX's first guess extrapolates the last
    increment's displacement rate, which is right only when the load is linear in step time.)
    `auto`: CalculiX's own incrementation from 0.1 (it grows after two easy increments)."""
    cards = ["*STEP, NLGEOM, INC=1000", "*STATIC", "0.1, 1., 1.e-5, 0.25" if steps == "ours" else "0.1, 1."]
    if steps == "ours":  # I_0, I_R, I_P, I_C, I_L, I_G, I_S, I_A; D_F, D_C, D_B, D_A, D_S, D_H, D_D
        cards += ["*CONTROLS, PARAMETERS=TIME INCREMENTATION", "4, 8, 9, 16, 10, 99, , 5", ", , , , , , 1.5"]
    if tolerance == "tight":  # R_n, C_n, q0, qu, R_p, eps, C_eps, R_l
        cards += ["*CONTROLS, PARAMETERS=FIELD", "1.e-8, 1.e-6, , , 1.e-8, 1.e-10, 1.e-6, 1.e-10"]
    return cards


def deck(args, mesh):
    sets, ref, rot = node_sets(mesh, args.load)
    lines = mesh.deck(args.element) + sets + material(args.law) + static(args.steps, args.tolerance)
    lines += boundary(mesh, args.load, ref, rot)
    lines += ["*NODE PRINT, NSET=END", "U, RF", "*NODE PRINT, NSET=MID", "U"]
    lines += ["*NODE PRINT, NSET=PILOT", "U, RF"] if args.load == "rigid" else []
    return lines + ["*END STEP"], rot


def last_block(dat, kind, nset):
    """{node: (a, b, c)} of the last *NODE PRINT block of `kind` (displacements | forces) for nset."""
    pattern = r"^ *%s \([^)]*\) for set %s and time[^\n]*\n\s*\n((?: *\d+(?: +\S+){3}\n)+)" % (kind, nset)
    rows = re.findall(pattern, dat, re.M | re.I)[-1]
    return {int(r.split()[0]): tuple(float(v) for v in r.split()[1:]) for r in rows.strip().splitlines()}


def moment_from_nodes(mesh, dat):
    """M_y about the centre from the end nodes' forces at deformed positions X + U."""
    u, f = last_block(dat, "displacements", "END"), last_block(dat, "forces", "END")
    total = 0.0
    for nid, force in f.items():
        x, _, z = (c + d for c, d in zip(mesh.coordinates(*mesh.used[nid]), u[nid]))
        total += (z - CENTRE[2]) * force[0] - (x - CENTRE[0]) * force[2]
    return total


def increments(sta):
    """(load factors reached, Newton iterations) from the .sta file's rows STEP INC ATT ITRS TOT-TIME
    (a row per converged increment; a cut back attempt's iterations are not counted)."""
    rows = [l.split() for l in sta.splitlines() if re.match(r"^\s*\d+\s+\d+\s+\d+\s+\d+\s", l)]
    return [float(r[4]) for r in rows], sum(int(r[3]) for r in rows)


def main():
    args = arguments()
    n = args.n
    mesh = Hex20Grid((graded(0.0, 20.0, 20 * n, args.grade, 0), uniform(-2.5, 2.5, 4 * n), uniform(-0.5, 0.5, n)))
    os.makedirs(args.work, exist_ok=True)
    lines, rot = deck(args, mesh)
    if args.deck_only:
        with open(os.path.join(args.work, "job.inp"), "w") as f:
            f.write("\n".join(lines) + "\n")
        return
    wall, memory = run_ccx(args.work, lines)
    dat = open(os.path.join(args.work, "job.dat")).read()
    by_nodes = moment_from_nodes(mesh, dat)
    by_pilot = last_block(dat, "forces", "PILOT")[rot][1] if rot else float("nan")
    factors, newton = increments(open(os.path.join(args.work, "job.sta")).read())
    deflection = list(last_block(dat, "displacements", "MID").values())[0][2]
    print(json.dumps({"dofs": 3 * len(mesh.used), "qoi": by_nodes,
                      "moment_y_rot_node": by_pilot, "moment_y_end_nodes": by_nodes, "deflection": deflection,
                      "increments": len(factors), "factors": factors, "iterations": newton, "wall_s": wall, "memory_mb": memory,
                      "element": args.element, "law": args.law, "load": args.load, "steps": args.steps}))


if __name__ == "__main__":
    main()
