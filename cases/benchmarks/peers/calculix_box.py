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
Writes the deck into WORK, runs ccx, prints one JSON line. Run: calculix_box.py PROBLEM N WORK"""
import json
import math
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hinge_mesh  # noqa: E402

problem, n, work = sys.argv[1], int(sys.argv[2]), sys.argv[3]


def uniform(lo, hi, cells):
    return [lo + (hi - lo) * i / cells for i in range(cells + 1)]


if problem == "cantilever":
    lines_xyz = uniform(0.0, 10.0, 10 * n), uniform(-0.5, 0.5, n), uniform(-0.5, 0.5, n)
elif problem == "leaf":
    lines_xyz = uniform(0.0, 40.0, 5 * n), uniform(-5.0, 5.0, 10 * n), uniform(-0.5, 0.5, n)
elif problem == "hinge":
    *lines_xyz, hinge_cells = hinge_mesh.grid(n)
else:
    sys.exit("unknown problem '%s' (cantilever | leaf | hinge)" % problem)
nx, ny, nz = (len(g) - 1 for g in lines_xyz)
cell_list = hinge_cells if problem == "hinge" else [(a, b, c) for c in range(nz) for b in range(ny) for a in range(nx)]
os.makedirs(work, exist_ok=True)


def node_id(i, j, k):  # on the (2nx+1) x (2ny+1) x (2nz+1) grid of corner and mid-side points
    return 1 + i + (2 * nx + 1) * (j + (2 * ny + 1) * k)


def coordinates(i, j, k):  # even indices on the grid lines, odd ones half-way between
    return tuple(g[c // 2] if c % 2 == 0 else 0.5 * (g[c // 2] + g[c // 2 + 1]) for g, c in zip(lines_xyz, (i, j, k)))


# Local corner/mid-side offsets in CalculiX's C3D20 order (corners 1-8, then edges 9-20).
order = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
         (1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
         (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
elements, used = [], {}
for a, b, c in cell_list:
    ids = []
    for di, dj, dk in order:
        ijk = (2 * a + di, 2 * b + dj, 2 * c + dk)
        used[node_id(*ijk)] = ijk
        ids.append(node_id(*ijk))
    elements.append(ids)
lines = ["*NODE"] + ["%d, %.12g, %.12g, %.12g" % ((nid,) + coordinates(*ijk)) for nid, ijk in sorted(used.items())]
lines.append("*ELEMENT, TYPE=C3D20R, ELSET=EALL")
for e, ids in enumerate(elements):
    lines.append("%d, %s," % (e + 1, ", ".join(map(str, ids[:15]))))
    lines.append(", ".join(map(str, ids[15:])))
fixed = sorted(nid for nid, ijk in used.items() if ijk[0] == 0)
lines += ["*NSET, NSET=FIX"] + ["%d," % f for f in fixed]
lines += ["*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3", "*DENSITY", "1.",
          "*SOLID SECTION, ELSET=EALL, MATERIAL=M", "*STEP", "*STATIC", "*BOUNDARY", "FIX, 1, 3"]
if problem == "cantilever":
    tip = node_id(2 * nx, ny, nz)
    lines += ["*DLOAD", "EALL, GRAV, 1., 0., 0., -1.", "*NSET, NSET=TIP", "%d," % tip, "*NODE PRINT, NSET=TIP", "U"]
elif problem == "leaf":
    theta = math.radians(1.0)
    for nid, ijk in sorted(used.items()):
        if ijk[0] == 2 * nx:
            _, y, z = coordinates(*ijk)
            lines += ["%d, 1, 1, 0." % nid,
                      "%d, 2, 2, %.10g" % (nid, y * (math.cos(theta) - 1) - z * math.sin(theta)),  # ccx reads 20 characters
                      "%d, 3, 3, %.10g" % (nid, y * math.sin(theta) + z * (math.cos(theta) - 1))]
    lines += ["*EL PRINT, ELSET=EALL, TOTALS=ONLY", "ELSE"]
else:
    for nid, ijk in sorted(used.items()):
        if ijk[0] == 2 * nx:
            x, y, _ = coordinates(*ijk)
            ux, uy = hinge_mesh.turned_displacement(x, y)
            lines += ["%d, 1, 1, %.10g" % (nid, ux), "%d, 2, 2, %.10g" % (nid, uy), "%d, 3, 3, 0." % nid]
    lines += ["*EL PRINT, ELSET=EALL, TOTALS=ONLY", "ELSE"]
lines.append("*END STEP")
with open(os.path.join(work, "job.inp"), "w") as f:
    f.write("\n".join(lines) + "\n")

env = dict(os.environ, OMP_NUM_THREADS="2", CCX_NPROC_EQUATION_SOLVER="2")
start = time.perf_counter()
proc = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M", "ccx", "-i", "job"], cwd=work,
                      capture_output=True, text=True, env=env)
wall = time.perf_counter() - start
if proc.returncode != 0:
    sys.exit("ccx failed: " + proc.stdout[-500:] + proc.stderr[-500:])
dat = open(os.path.join(work, "job.dat")).read()
if problem == "cantilever":
    qoi = float(re.findall(r"^\s*%d\s+(\S+)\s+(\S+)\s+(\S+)" % tip, dat, re.M)[-1][2])
else:
    qoi = float(re.findall(r"total internal energy[^\n]*\n\s*\n?\s*(\S+)", dat)[-1])
memory = float(re.findall(r"MAXRSS (\d+)", proc.stderr)[-1]) / 1024.0
print(json.dumps({"dofs": 3 * len(used), "qoi": qoi, "wall_s": wall, "memory_mb": memory, "iterations": 1}))
