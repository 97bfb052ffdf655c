#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx) on the benchmark cantilever: 10 x 1 x 1 box,
n x n x 10n hexahedra, Lagrange degree 2, E = 1000, nu = 0.3, body load (0, 0, -1), clamped at
x = 0. CG + GAMG given the block size (vector space) and the rigid-body near null space, as in
the dolfinx elasticity demo, relative tolerance 1e-10 like ours. Prints one JSON line (rank 0).
Run: mpirun -np 2 /usr/bin/python3 fenicsx_cantilever.py N"""
import json
import os
import resource
import sys
import time

t_start = time.perf_counter()
import numpy as np  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem, mesh  # noqa: E402
from dolfinx.fem.petsc import apply_lifting, assemble_matrix, assemble_vector, set_bc  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import GAMG_OPTIONS, rigid_body_near_null_space  # noqa: E402

n = int(sys.argv[1])
comm = MPI.COMM_WORLD
domain = mesh.create_box(comm, [np.array([0.0, -0.5, -0.5]), np.array([10.0, 0.5, 0.5])],
                         [10 * n, n, n], mesh.CellType.hexahedron)
V = fem.VectorFunctionSpace(domain, ("Lagrange", 2))
E, nu = 1000.0, 0.3
mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
u, v = ufl.TrialFunction(V), ufl.TestFunction(V)


def sigma(w):
    eps = ufl.sym(ufl.grad(w))
    return 2 * mu * eps + lmbda * ufl.tr(eps) * ufl.Identity(3)


f = fem.Constant(domain, PETSc.ScalarType((0.0, 0.0, -1.0)))
a = fem.form(ufl.inner(sigma(u), ufl.grad(v)) * ufl.dx)
L = fem.form(ufl.inner(f, v) * ufl.dx)
clamped = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 0.0))
bc = fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamped, V)

t_assemble = time.perf_counter()
A = assemble_matrix(a, bcs=[bc])
A.assemble()
b = assemble_vector(L)
apply_lifting(b, [a], bcs=[[bc]])
b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
set_bc(b, [bc])

index_map, bs = V.dofmap.index_map, V.dofmap.index_map_bs
A.setNearNullSpace(rigid_body_near_null_space(V))
t_solve = time.perf_counter()

ksp = PETSc.KSP().create(comm)
ksp.setOperators(A)
opts = PETSc.Options()
for key, value in GAMG_OPTIONS.items():
    opts[key] = value
ksp.setFromOptions()
uh = fem.Function(V)
ksp.solve(b, uh.vector)
uh.x.scatter_forward()
t_end = time.perf_counter()

# Tip deflection at (10, 0, 0): a node of the Q2 mesh for every n.
coords = V.tabulate_dof_coordinates()[: index_map.size_local]
hit = np.where(np.linalg.norm(coords - np.array([10.0, 0.0, 0.0]), axis=1) < 1e-8)[0]
local = uh.x.array[3 * hit[0] + 2] if len(hit) else 0.0
tip = comm.allreduce(local, op=MPI.SUM) / max(comm.allreduce(len(hit), op=MPI.SUM), 1)
memory = comm.allreduce(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, op=MPI.MAX)
if comm.rank == 0:
    print(json.dumps({"dofs": V.dofmap.index_map.size_global * bs, "qoi": tip,
                      "solve_s": t_end - t_solve, "assembly_s": t_solve - t_assemble,
                      "iterations": ksp.getIterationNumber(), "memory_mb": memory,
                      "in_process_s": t_end - t_start}))
