#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx): the plane-stress cantilever of
cases/verification/cantilever_2d.prm, an independent reference for the tests (issue 34). L x H
(y from -H/2 to H/2), E = 200000, nu = 0.3, clamped at x = 0, a total force -1 spread evenly over
x = L; the mean vertical displacement of that edge (integral over the edge / H). Lagrange degree
p on (ny L/H) x ny square quadrilaterals, MUMPS. Prints one JSON line per mesh (rank 0).
Run: mpirun -np 1 /usr/bin/python3 fenicsx_cantilever_2d.py L H p NY [NY ...]"""
import json
import os
import sys

import numpy as np
from dolfinx import fem, mesh
from mpi4py import MPI

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import solve_clamped_plane_stress  # noqa: E402

comm = MPI.COMM_WORLD
L, H, degree = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3])
E, nu = 200000.0, 0.3


def solve(ny):
    nx = int(round(ny * L / H))
    domain = mesh.create_rectangle(comm, [np.array([0.0, -H / 2]), np.array([L, H / 2])], [nx, ny],
                                   mesh.CellType.quadrilateral)
    uh, ds = solve_clamped_plane_stress(domain, degree, E, nu, 0.0, L, (0.0, -1.0 / H))
    V = uh.function_space
    mean = comm.allreduce(fem.assemble_scalar(fem.form(uh[1] * ds(1))), op=MPI.SUM) / H
    return V.dofmap.index_map.size_global * 2, mean


for ny in [int(a) for a in sys.argv[4:]]:
    dofs, mean = solve(ny)
    if comm.rank == 0:
        print(json.dumps({"ny": ny, "degree": degree, "dofs": dofs, "mean_displacement_right_y": mean}), flush=True)
