#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx) on the benchmark cantilever: 10 x 1 x 1 box,
n x n x 10n hexahedra, Lagrange degree 2, E = 1000, nu = 0.3, body load (0, 0, -1), clamped at
x = 0. CG + GAMG given the block size (vector space) and the rigid-body near null space, as in
the dolfinx elasticity demo, relative tolerance 1e-10 like ours. Prints one JSON line (rank 0).
Run: mpirun -np 2 /usr/bin/python3 fenicsx_cantilever.py N"""
import json
import resource
import sys
import time

t_start = time.perf_counter()
import numpy as np  # noqa: E402
import ufl  # noqa: E402
from dolfinx import fem, la, mesh  # noqa: E402
from dolfinx.fem.petsc import apply_lifting, assemble_matrix, assemble_vector, set_bc  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

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

# Rigid-body modes as near null space (translations and rotations), orthonormalized.
index_map, bs = V.dofmap.index_map, V.dofmap.index_map_bs
modes = [la.create_petsc_vector(index_map, bs) for _ in range(6)]
with modes[0].localForm() as b0, modes[1].localForm() as b1, modes[2].localForm() as b2, \
        modes[3].localForm() as b3, modes[4].localForm() as b4, modes[5].localForm() as b5:
    basis = [np.asarray(x) for x in (b0, b1, b2, b3, b4, b5)]
    dofs = [V.sub(i).dofmap.list.array for i in range(3)]
    for i in range(3):
        basis[i][dofs[i]] = 1.0
    x = V.tabulate_dof_coordinates()
    d = V.dofmap.list.array  # node (block) indices, matching dofs[i] entry by entry
    x0, x1, x2 = x[d, 0], x[d, 1], x[d, 2]
    basis[3][dofs[0]] = -x1
    basis[3][dofs[1]] = x0
    basis[4][dofs[0]] = x2
    basis[4][dofs[2]] = -x0
    basis[5][dofs[2]] = x1
    basis[5][dofs[1]] = -x2
la.orthonormalize(modes)
A.setNearNullSpace(PETSc.NullSpace().create(vectors=modes))
t_solve = time.perf_counter()

ksp = PETSc.KSP().create(comm)
ksp.setOperators(A)
opts = PETSc.Options()
opts["ksp_type"] = "cg"
opts["ksp_rtol"] = 1.0e-10
opts["pc_type"] = "gamg"
opts["mg_levels_ksp_type"] = "chebyshev"
opts["mg_levels_pc_type"] = "jacobi"
opts["mg_levels_esteig_ksp_type"] = "cg"
opts["mg_levels_ksp_chebyshev_esteig_steps"] = 20
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
