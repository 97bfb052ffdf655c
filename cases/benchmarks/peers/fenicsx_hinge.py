#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5) on the 3D blade flexure hinge (cases/benchmarks/hinge_3d.prm), the structured
hexahedral mesh of hinge_mesh.py at level M (the same cells ours and CalculiX solve), Lagrange
degree 2, E = 1000, nu = 0.3, clamped at x = 0, the end x = 24 turned rigidly by 1 degree about the
z axis through (12, 0) (the exact rotation, as ours). CG + GAMG with block size and rigid-body modes,
relative tolerance 1e-10. QoI: strain energy. One JSON line on rank 0.
Run: mpirun -np 2 /usr/bin/python3 fenicsx_hinge.py M"""
import math
import os
import sys
import time

t_start = time.perf_counter()
import numpy as np  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem, mesh  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

m = int(sys.argv[1])
comm = MPI.COMM_WORLD
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hinge_mesh  # noqa: E402
from fenicsx_common import solve_and_report_energy  # noqa: E402

# Rank 0 gives every cell (dolfinx's tensor-product vertex order), create_mesh partitions them.
xs, ys, zs, cell_list = hinge_mesh.grid(m)
nx, ny = len(xs), len(ys)
if comm.rank == 0:
    points = np.array([(x, y, z) for z in zs for y in ys for x in xs])
    cells = np.array([[i + di + nx * (j + dj + ny * (k + dk)) for dk in (0, 1) for dj in (0, 1) for di in (0, 1)]
                      for i, j, k in cell_list], dtype=np.int64)
else:
    points, cells = np.zeros((0, 3)), np.zeros((0, 8), dtype=np.int64)
domain = mesh.create_mesh(comm, cells, points, ufl.Mesh(ufl.VectorElement("Lagrange", ufl.hexahedron, 1)))
x_end = xs[-1]
V = fem.VectorFunctionSpace(domain, ("Lagrange", 2))
E, nu = 1000.0, 0.3
theta = math.radians(hinge_mesh.ANGLE_DEG)

clamped = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 0.0))
turned = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], x_end))
rotation = fem.Function(V)
cx, cy = hinge_mesh.CENTER
rotation.interpolate(lambda x: np.vstack(((x[0] - cx) * (math.cos(theta) - 1) - (x[1] - cy) * math.sin(theta),
                                          (x[0] - cx) * math.sin(theta) + (x[1] - cy) * (math.cos(theta) - 1),
                                          0 * x[0])))
bcs = [fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamped, V), fem.dirichletbc(rotation, turned)]
solve_and_report_energy(V, E, nu, bcs)
