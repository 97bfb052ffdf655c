#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx): Cook's membrane, linear plane stress, an
independent reference for the tests (issue 34). Trapezoid (0,0), (48,44), (48,60), (0,44), E = 1,
nu = 1/3, clamped at x = 0, a total shear force 1 spread evenly over the right edge (1/16 per unit
length), Lagrange degree 2 on n x n quadrilaterals (the bilinear map of a structured square mesh,
the same cells as meshes/cook_membrane.geo), MUMPS. Prints one JSON line (rank 0) with the vertical
displacement at the middle of the loaded edge (48, 52) and at the top corner (48, 60).
Run: mpirun -np 2 /usr/bin/python3 fenicsx_cook.py N [N ...]"""
import json
import os
import sys

import numpy as np
from dolfinx import mesh
from mpi4py import MPI

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import solve_clamped_plane_stress  # noqa: E402

comm = MPI.COMM_WORLD
E, nu = 1.0, 1.0 / 3.0


def solve(n):
    domain = mesh.create_unit_square(comm, n, n, mesh.CellType.quadrilateral)
    x = domain.geometry.x
    xi, eta = x[:, 0].copy(), x[:, 1].copy()
    x[:, 0] = 48 * xi
    x[:, 1] = 44 * xi + eta * (44 - 28 * xi)
    uh, _ = solve_clamped_plane_stress(domain, 2, E, nu, 0.0, 48.0, (0.0, 1.0 / 16.0))
    V = uh.function_space
    index_map = V.dofmap.index_map
    coords = V.tabulate_dof_coordinates()[: index_map.size_local]
    values = {}
    for name, point in (("mid", (48.0, 52.0)), ("corner", (48.0, 60.0))):
        hit = np.where(np.linalg.norm(coords[:, :2] - np.array(point), axis=1) < 1e-9)[0]
        local = uh.x.array[2 * hit[0] + 1] if len(hit) else 0.0
        values[name] = comm.allreduce(local, op=MPI.SUM) / max(comm.allreduce(len(hit), op=MPI.SUM), 1)
    return index_map.size_global * 2, values


for n in [int(a) for a in sys.argv[1:]]:
    dofs, values = solve(n)
    if comm.rank == 0:
        print(json.dumps({"n": n, "dofs": dofs, "mid_y": values["mid"], "corner_y": values["corner"]}), flush=True)
