#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5) on the leaf-torsion benchmark (cases/benchmarks/leaf_torsion.prm): 40 x 10 x 1
plate, 5m x 10m x m hexahedra, Lagrange degree 2, E = 1000, nu = 0.3, clamped at x = 0, the end
x = 40 turned rigidly by 1 degree about the x axis (the exact rotation, as ours). CG + GAMG with block
size and rigid-body modes, relative tolerance 1e-10. QoI: strain energy. One JSON line on rank 0.
Run: mpirun -np 2 /usr/bin/python3 fenicsx_leaf.py M"""
import math
import os
import sys
import time

t_start = time.perf_counter()
import numpy as np  # noqa: E402
from dolfinx import fem, mesh  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import solve_and_report_energy  # noqa: E402

m = int(sys.argv[1])
comm = MPI.COMM_WORLD
domain = mesh.create_box(comm, [np.array([0.0, -5.0, -0.5]), np.array([40.0, 5.0, 0.5])],
                         [5 * m, 10 * m, m], mesh.CellType.hexahedron)
V = fem.VectorFunctionSpace(domain, ("Lagrange", 2))
E, nu = 1000.0, 0.3
theta = math.radians(1.0)

clamped = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 0.0))
turned = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 40.0))
rotation = fem.Function(V)
rotation.interpolate(lambda x: np.vstack((0 * x[0], x[1] * (math.cos(theta) - 1) - x[2] * math.sin(theta),
                                          x[1] * math.sin(theta) + x[2] * (math.cos(theta) - 1))))
bcs = [fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamped, V), fem.dirichletbc(rotation, turned)]
solve_and_report_energy(V, E, nu, bcs)
