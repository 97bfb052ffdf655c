#!/usr/bin/python3
"""CalculiX (Debian's calculix-ccx) on the benchmark cantilever: 10 x 1 x 1, n x n x 10n C3D20R
(20-node serendipity hexahedra, reduced integration), E = 1000, nu = 0.3, body load through GRAV
with density 1, clamped at x = 0. Writes the input deck into a work folder, runs ccx with 2 threads
(its default SPOOLES solver), prints one JSON line. Run: calculix_cantilever.py N WORKDIR"""
import json
import os
import re
import subprocess
import sys
import time

n, work = int(sys.argv[1]), sys.argv[2]
nx, ny, nz = 10 * n, n, n
os.makedirs(work, exist_ok=True)


def node_id(i, j, k):  # on the (2nx+1) x (2ny+1) x (2nz+1) grid of corner and mid-side points
    return 1 + i + (2 * nx + 1) * (j + (2 * ny + 1) * k)


# Local corner/mid-side offsets in CalculiX's C3D20 order (corners 1-8, then edges 9-20).
order = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
         (1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
         (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]
elements, used = [], set()
for c in range(nz):
    for b in range(ny):
        for a in range(nx):
            ids = [node_id(2 * a + di, 2 * b + dj, 2 * c + dk) for di, dj, dk in order]
            elements.append(ids)
            used.update(ids)
lines = ["*NODE"]
for k in range(2 * nz + 1):
    for j in range(2 * ny + 1):
        for i in range(2 * nx + 1):
            nid = node_id(i, j, k)
            if nid in used:
                lines.append("%d, %.12g, %.12g, %.12g" % (nid, 10.0 * i / (2 * nx), -0.5 + j / (2 * ny),
                                                           -0.5 + k / (2 * nz)))
lines.append("*ELEMENT, TYPE=C3D20R, ELSET=EALL")
for e, ids in enumerate(elements):
    lines.append("%d, %s," % (e + 1, ", ".join(map(str, ids[:15]))))
    lines.append(", ".join(map(str, ids[15:])))
fixed = sorted(nid for nid in used if (nid - 1) % (2 * nx + 1) == 0)
tip = node_id(2 * nx, ny, nz)
lines += ["*NSET, NSET=FIX"] + ["%d," % f for f in fixed]
lines += ["*NSET, NSET=TIP", "%d," % tip,
          "*MATERIAL, NAME=M", "*ELASTIC", "1000., 0.3", "*DENSITY", "1.",
          "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
          "*STEP", "*STATIC", "*BOUNDARY", "FIX, 1, 3", "*DLOAD", "EALL, GRAV, 1., 0., 0., -1.",
          "*NODE PRINT, NSET=TIP", "U", "*END STEP"]
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
row = re.findall(r"^\s*%d\s+(\S+)\s+(\S+)\s+(\S+)" % tip, dat, re.M)[-1]
memory = float(re.findall(r"MAXRSS (\d+)", proc.stderr)[-1]) / 1024.0
print(json.dumps({"dofs": 3 * len(used), "qoi": float(row[2]), "wall_s": wall, "memory_mb": memory,
                  "iterations": 1}))
