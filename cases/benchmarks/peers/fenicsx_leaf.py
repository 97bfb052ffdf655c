#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5) on the leaf-torsion benchmark (cases/benchmarks/leaf_torsion.prm): 40 x 10 x 1
plate, 5m x 10m x m hexahedra, Lagrange degree 2, E = 1000, nu = 0.3, clamped at x = 0, the end
x = 40 turned rigidly by 1 degree about the x axis (the exact rotation, as ours). CG + GAMG with block
size and rigid-body modes, relative tolerance 1e-10. QoI: strain energy. One JSON line on rank 0.
Run: mpirun -np 2 /usr/bin/python3 fenicsx_leaf.py M"""
import json
import math
import os
import resource
import sys
import time

t_start = time.perf_counter()
import numpy as np  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem, mesh  # noqa: E402
from dolfinx.fem.petsc import LinearProblem  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import GAMG_OPTIONS, rigid_body_near_null_space  # noqa: E402

m = int(sys.argv[1])
comm = MPI.COMM_WORLD
domain = mesh.create_box(comm, [np.array([0.0, -5.0, -0.5]), np.array([40.0, 5.0, 0.5])],
                         [5 * m, 10 * m, m], mesh.CellType.hexahedron)
V = fem.VectorFunctionSpace(domain, ("Lagrange", 2))
E, nu = 1000.0, 0.3
mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
theta = math.radians(1.0)


def eps(w):
    return ufl.sym(ufl.grad(w))


def sigma(w):
    return 2 * mu * eps(w) + lmbda * ufl.tr(eps(w)) * ufl.Identity(3)


u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
clamped = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 0.0))
turned = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 40.0))
rotation = fem.Function(V)
rotation.interpolate(lambda x: np.vstack((0 * x[0], x[1] * (math.cos(theta) - 1) - x[2] * math.sin(theta),
                                          x[1] * math.sin(theta) + x[2] * (math.cos(theta) - 1))))
bcs = [fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamped, V), fem.dirichletbc(rotation, turned)]
zero = fem.Constant(domain, PETSc.ScalarType((0.0, 0.0, 0.0)))
problem = LinearProblem(ufl.inner(sigma(u), eps(v)) * ufl.dx, ufl.inner(zero, v) * ufl.dx, bcs=bcs,
                        petsc_options=GAMG_OPTIONS)
index_map, bs = V.dofmap.index_map, V.dofmap.index_map_bs
problem.A.setNearNullSpace(rigid_body_near_null_space(V))
t_solve = time.perf_counter()
uh = problem.solve()
t_end = time.perf_counter()
energy = comm.allreduce(fem.assemble_scalar(fem.form(0.5 * ufl.inner(sigma(uh), eps(uh)) * ufl.dx)), op=MPI.SUM)
memory = comm.allreduce(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, op=MPI.MAX)
if comm.rank == 0:
    print(json.dumps({"dofs": index_map.size_global * bs, "qoi": energy, "solve_s": t_end - t_solve,
                      "iterations": problem.solver.getIterationNumber(), "memory_mb": memory}))
