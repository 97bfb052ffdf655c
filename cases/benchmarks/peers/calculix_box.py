#!/usr/bin/python3
"""CalculiX (Debian's calculix-ccx) on the benchmark boxes, C3D20R (20-node serendipity hexahedra,
reduced integration), E = 1000, nu = 0.3, its default SPOOLES solver with 2 threads:
  cantilever N: 10 x 1 x 1, 10N x N x N cells, body load (0, 0, -1) through GRAV with density 1,
                clamped at x = 0; QoI the tip deflection at (10, 0, 0);
  hinge M:      the 3D blade flexure hinge of hinge_mesh.py (same cells as ours and FEniCSx), clamped
                at x = 0, x = 24 turned rigidly by 1 degree about the z axis through (12, 0); QoI the
                strain energy;
  leaf M:       40 x 10 x 1, 5M x 10M x M cells, clamped at x = 0, x = 40 turned rigidly by 1 degree
                about the x axis (exact rotation per node); QoI the strain energy (*EL PRINT ELSE).
GRADE (default 1): the cells along x graded as meshes/graded_layers.geo grades ours, the longest GRADE
times the shortest, toward the clamp (cantilever) or both ends (leaf); the hinge's every x segment
toward both its ends and the blocks' y segments toward the blade (hinge_mesh.py).
Writes the deck into WORK, runs ccx, prints one JSON line. Run: calculix_box.py PROBLEM N WORK [GRADE]"""
import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hinge_mesh  # noqa: E402
from calculix_common import Hex20Grid, graded, run_ccx, uniform  # noqa: E402

problem, n, work = sys.argv[1], int(sys.argv[2]), sys.argv[3]
grade = float(sys.argv[4]) if len(sys.argv) > 4 else 1.0

if problem == "cantilever":
    lines_xyz = graded(0.0, 10.0, 10 * n, grade, 1), uniform(-0.5, 0.5, n), uniform(-0.5, 0.5, n)
elif problem == "leaf":
    lines_xyz = graded(0.0, 40.0, 5 * n, grade, 0), uniform(-5.0, 5.0, 10 * n), uniform(-0.5, 0.5, n)
elif problem == "hinge":
    *lines_xyz, hinge_cells = hinge_mesh.grid(n, grade)
else:
    sys.exit("unknown problem '%s' (cantilever | leaf | hinge)" % problem)
mesh = Hex20Grid(lines_xyz, hinge_cells if problem == "hinge" else None)
os.makedirs(work, exist_ok=True)

lines = mesh.deck("C3D20R")
fixed = mesh.nodes_where(0, 0)
lines += ["*NSET, NSET=FIX"] + ["%d," % f for f in fixed]
lines += ["*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3", "*DENSITY", "1.",
          "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*STATIC", "*BOUNDARY", "FIX, 1, 3"]
if problem == "cantilever":
    tip = mesh.node_id(2 * mesh.nx, mesh.ny, mesh.nz)
    lines += ["*DLOAD", "EALL, GRAV, 1., 0., 0., -1.", "*NSET, NSET=TIP", "%d," % tip, "*NODE PRINT, NSET=TIP", "U"]
elif problem == "leaf":
    theta = math.radians(1.0)
    for nid in mesh.nodes_where(0, 2 * mesh.nx):
        _, y, z = mesh.coordinates(*mesh.used[nid])
        lines += ["%d, 1, 1, 0." % nid,
                  "%d, 2, 2, %.10g" % (nid, y * (math.cos(theta) - 1) - z * math.sin(theta)),  # ccx reads 20 characters
                  "%d, 3, 3, %.10g" % (nid, y * math.sin(theta) + z * (math.cos(theta) - 1))]
    lines += ["*EL PRINT, ELSET=EALL, TOTALS=ONLY", "ELSE"]
else:
    for nid in mesh.nodes_where(0, 2 * mesh.nx):
        x, y, _ = mesh.coordinates(*mesh.used[nid])
        ux, uy = hinge_mesh.turned_displacement(x, y)
        lines += ["%d, 1, 1, %.10g" % (nid, ux), "%d, 2, 2, %.10g" % (nid, uy), "%d, 3, 3, 0." % nid]
    lines += ["*EL PRINT, ELSET=EALL, TOTALS=ONLY", "ELSE"]
lines.append("*END STEP")
wall, memory = run_ccx(work, lines)
dat = open(os.path.join(work, "job.dat")).read()
if problem == "cantilever":
    qoi = float(re.findall(r"^\s*%d\s+(\S+)\s+(\S+)\s+(\S+)" % tip, dat, re.M)[-1][2])
else:
    qoi = float(re.findall(r"total internal energy[^\n]*\n\s*\n?\s*(\S+)", dat)[-1])
print(json.dumps({"dofs": 3 * len(mesh.used), "qoi": qoi, "wall_s": wall, "memory_mb": memory, "iterations": 1}))
