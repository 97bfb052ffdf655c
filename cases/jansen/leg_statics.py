#!/usr/bin/python3
"""Statics hand check of the Jansen leg with ideal pins (the reference for the FE joint forces).

    leg_statics.py [--theta2 DEG] [--load FX FY] [--load-point X Y] [--summary summary.json] [--tolerance 0.02]

The crank is held by the motor at A (force and moment), E is a pin to the ground, the foot load
acts at H. With the crank held the leg is a statically determinate structure of seven rigid
links: 7 x 3 equilibrium equations of the links and 2 x 5 of the free pins B, C, D, F, G give
the 31 unknowns (two force components per link end, the motor's force and moment at A). The
pose is assembled from the paper's link lengths with the same circle intersections as the
kinematics library and meshes/jansen_leg.geo. --load-point puts the load's line of action
through another point of the foot link (the ground's contact point, cases/jansen/leg_ground_contact.prm).

With --summary, compares the forces the pins put on each link, as the FE linkage analysis
reports them (reaction_force_eye_<link>_<joint>_x|y), the motor moment and the pin moments, and
exits 1 if a joint force differs by more than the tolerance times the largest joint force.
"""
import argparse
import json
import math
import sys

import numpy as np

LENGTHS = dict(EA=193.96, AB=75, BC=250, BG=309.5, CE=207.5, DE=200.5, CD=279, EG=196.5,
               DF=197, FG=183, GH=245, FH=328, theta1=11.6)  # paper's leg, mm and degrees
# Link name -> its joints; the load acts on FGH at H, the motor on the crank AB at A.
LINKS = {"AB": "AB", "BC": "BC", "BG": "BG", "CDE": "CDE", "EG": "EG", "DF": "DF", "FGH": "FG"}
FREE_PINS = "BCDFG"


def intersect(p1, p2, r1, r2, side):
    """Intersection of circles (p1, r1), (p2, r2) left (+1) or right (-1) of p1 -> p2."""
    d = math.dist(p1, p2)
    ux, uy = (p2[0] - p1[0]) / d, (p2[1] - p1[1]) / d
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(r1 * r1 - a * a)
    return (p1[0] + a * ux - side * h * uy, p1[1] + a * uy + side * h * ux)


def joints(theta2, L=LENGTHS):
    E = (0.0, 0.0)
    t1 = math.radians(L["theta1"])
    A = (L["EA"] * math.cos(t1), L["EA"] * math.sin(t1))
    t2 = math.radians(theta2)
    B = (A[0] + L["AB"] * math.cos(t2), A[1] + L["AB"] * math.sin(t2))
    C = intersect(B, E, L["BC"], L["CE"], -1)
    G = intersect(B, E, L["BG"], L["EG"], +1)
    D = intersect(E, C, L["DE"], L["CD"], +1)
    F = intersect(D, G, L["DF"], L["FG"], -1)
    H = intersect(G, F, L["GH"], L["FH"], +1)
    return dict(A=A, B=B, C=C, D=D, E=E, F=F, G=G, H=H)


def solve(theta2, load, point=None):
    P = joints(theta2)
    at = point if point is not None else P["H"]  # where the load acts on FGH
    unknowns = [(link, j) for link, js in LINKS.items() for j in js]  # force by pin j on link
    index = {u: 2 * k for k, u in enumerate(unknowns)}
    n = 2 * len(unknowns) + 1  # + motor moment on the crank
    motor = n - 1
    rows, rhs = [], []
    for link, js in LINKS.items():
        fx, fy, m = np.zeros(n), np.zeros(n), np.zeros(n)
        for j in js:
            k = index[(link, j)]
            fx[k] = fy[k + 1] = 1
            m[k], m[k + 1] = -P[j][1], P[j][0]  # moment about E of (Fx, Fy) at joint j
        bx = by = bm = 0.0
        if link == "FGH":  # external load at H
            bx, by = -load[0], -load[1]
            bm = -(at[0] * load[1] - at[1] * load[0])
        if link == "AB":
            m[motor] = 1
        rows += [fx, fy, m]
        rhs += [bx, by, bm]
    for pin in FREE_PINS:  # the forces of the pin on its links sum to zero
        for c in (0, 1):
            r = np.zeros(n)
            for (link, j), k in index.items():
                if j == pin:
                    r[k + c] = 1
            rows.append(r)
            rhs.append(0.0)
    x = np.linalg.solve(np.array(rows), np.array(rhs))
    forces = {u: x[index[u]:index[u] + 2] for u in unknowns}
    return P, forces, x[motor]


def ternary_moment_scale(P, forces, load, point=None):
    """Scale of the bending moments in the ternary links: the largest moment of the force at one
    corner (or the foot load) about another corner of the same link. (The sum over all corners
    vanishes by equilibrium; a single force's moment is what the bars between the corners carry.)"""
    largest = 0.0
    for link in ("CDE", "FGH"):
        acting = [(j, P[j], forces[(link, j)]) for j in LINKS[link]]
        if link == "FGH":
            acting.append(("H", point if point is not None else P["H"], np.array(load)))
        for j, p, f in acting:
            for corner in link:
                if corner != j:
                    m = (p[0] - P[corner][0]) * f[1] - (p[1] - P[corner][1]) * f[0]
                    largest = max(largest, abs(m))
    return largest


def fe_name(link, joint):
    return "eye_%s_%s" % ("AB" if link == "AB" else link, joint)


def fe_moment_about_joint(q, name, point):
    """The FE reports moments about the origin E; M_P = M_E - (P x F)."""
    fx, fy = q["reaction_force_%s_x" % name], q["reaction_force_%s_y" % name]
    return q["reaction_moment_%s_z" % name] - (point[0] * fy - point[1] * fx)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--theta2", type=float, default=37.2089)
    ap.add_argument("--load", type=float, nargs=2, default=[0.0, 500.0], help="force at H, N")
    ap.add_argument("--load-point", type=float, nargs=2, default=None,
                    help="a point of the load's line of action, mm (default H)")
    ap.add_argument("--summary", help="summary.json of the FE linkage run to compare")
    ap.add_argument("--tolerance", type=float, default=0.02)
    args = ap.parse_args()
    P, forces, motor = solve(args.theta2, args.load, args.load_point)
    scale = max(np.linalg.norm(f) for f in forces.values())
    q = json.load(open(args.summary))["quantities"] if args.summary else None
    print("theta2 = %g deg, load at H = (%g, %g) N, joints (mm): %s" % (
        args.theta2, args.load[0], args.load[1],
        ", ".join("%s (%.3f, %.3f)" % (k, v[0], v[1]) for k, v in P.items())))
    print("%-14s %12s %12s %12s" % ("pin on link", "Fx (N)", "Fy (N)", "|F| (N)") +
          ("   %12s %12s %9s %14s" % ("FE Fx", "FE Fy", "diff", "FE M (N mm)") if q else ""))
    worst = 0.0
    for (link, j), f in forces.items():
        line = "%-14s %12.3f %12.3f %12.3f" % (fe_name(link, j), f[0], f[1], np.linalg.norm(f))
        if q:
            name = fe_name(link, j)
            g = np.array([q["reaction_force_%s_x" % name], q["reaction_force_%s_y" % name]])
            diff = np.linalg.norm(g - f) / scale
            worst = max(worst, diff)
            line += "   %12.3f %12.3f %8.1e %14.3e" % (g[0], g[1], diff, fe_moment_about_joint(q, name, P[j]))
        print(line)
    print("motor moment on the crank at A: %.3f N mm" % motor +
          ("   FE: %.3f N mm" % fe_moment_about_joint(q, "eye_AB_A", P["A"]) if q else ""))
    bending = ternary_moment_scale(P, forces, args.load, args.load_point)
    print("moment scale of the ternary links (one corner's force about another corner): %.1f N mm" % bending)
    if q:
        pin_moments = [abs(fe_moment_about_joint(q, fe_name(l, j), P[j])) for (l, j) in forces if (l, j) != ("AB", "A")]
        ratio = max(pin_moments) / bending
        print("largest joint-force difference / largest joint force: %.2e (tolerance %g)" % (worst, args.tolerance))
        print("largest moment of a pin on a link: %.3e N mm = %.1e of that scale (tolerance %g)" % (
            max(pin_moments), ratio, args.tolerance))
        return 1 if worst > args.tolerance or ratio > args.tolerance else 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
