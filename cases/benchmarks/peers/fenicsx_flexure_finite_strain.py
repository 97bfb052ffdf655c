#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx) on cases/benchmarks/flexure_finite_strain.prm:
the TPU strip [0, 20] x [-2.5, 2.5] x [-0.5, 0.5] mm (Semiflex, E = 89.5 MPa, nu = 0.48) on
nx x ny x nz hexahedra, Lagrange degree 2, clamped at x = 0, the end x = 20 turned rigidly by 45
degrees about the axis (0, 1, 0) through (20, 2.5, 0.5), the same compressible neo-Hookean law and
quadrature (3 Gauss points a direction) as ours, W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, at our load factors (0.1, 0.25, 0.475,
0.725, 0.975, 1: the steps our step control takes on this problem), full Newton from the previous
step's solution, each linear step by MUMPS (`direct`) or CG + GAMG with the rigid-body modes
(`gamg`), until the residual at the free DoFs is below 1e-9 of the first one of the step.
Prints one JSON line (rank 0): DoFs, the reaction moment about y at the turned end (about the
rotation centre, at the deformed positions, as ours), the deflection u_z at (10, 2.5, 0.5), Newton
iterations, times. Run: mpirun -np 2 /usr/bin/python3 fenicsx_flexure_finite_strain.py (NX NY NZ | N)
[direct|gamg] (N: 20N x 4N x N cells)"""
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
from dolfinx.fem.petsc import apply_lifting, assemble_matrix, assemble_vector, set_bc  # noqa: E402
from mpi4py import MPI  # noqa: E402
from petsc4py import PETSc  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fenicsx_common import GAMG_OPTIONS, rigid_body_near_null_space  # noqa: E402

if len(sys.argv) in (2, 3):  # the benchmark's level N: 20N x 4N x N cells
    level = int(sys.argv[1])
    nx, ny, nz = 20 * level, 4 * level, level
    method = sys.argv[2] if len(sys.argv) > 2 else "direct"
else:
    nx, ny, nz = (int(v) for v in sys.argv[1:4])
    method = sys.argv[4] if len(sys.argv) > 4 else "direct"
LOAD_FACTORS = (0.1, 0.25, 0.475, 0.725, 0.975, 1.0)
ANGLE, CENTRE = math.radians(45.0), np.array([20.0, 2.5, 0.5])
E, nu = 89.5, 0.48
mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))

comm = MPI.COMM_WORLD
domain = mesh.create_box(comm, [np.array([0.0, -2.5, -0.5]), np.array([20.0, 2.5, 0.5])], [nx, ny, nz],
                         mesh.CellType.hexahedron)
V = fem.VectorFunctionSpace(domain, ("Lagrange", 2))
u, v, du = fem.Function(V), ufl.TestFunction(V), ufl.TrialFunction(V)
F = ufl.Identity(3) + ufl.grad(u)
C = F.T * F
J = ufl.det(F)
W = mu / 2 * (ufl.tr(C) - 3) - mu * ufl.ln(J) + lmbda / 2 * ufl.ln(J) ** 2
# 3 x 3 x 3 Gauss points per cell, as ours (QGauss(degree + 1)); UFL's own estimate for ln J would
# take hundreds and change the answer in the fourth digit.
dx = ufl.dx(metadata={"quadrature_degree": 4})
residual_form = ufl.derivative(W * dx, u, v)
residual = fem.form(residual_form)
tangent = fem.form(ufl.derivative(residual_form, u, du))

left = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 0.0))
right = fem.locate_dofs_geometrical(V, lambda x: np.isclose(x[0], 20.0))
turned = fem.Function(V)
bcs = [fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), left, V), fem.dirichletbc(turned, right)]


def turn(theta):
    """The rigid turn of the end: u = R (X - c) + c - X about y (z towards x)."""
    def value(x):
        dx, dz = x[0] - CENTRE[0], x[2] - CENTRE[2]
        return np.vstack((math.cos(theta) * dx + math.sin(theta) * dz - dx, np.zeros_like(dx),
                          -math.sin(theta) * dx + math.cos(theta) * dz - dz))
    turned.interpolate(value)


ksp = PETSc.KSP().create(comm)
opts = PETSc.Options()
options = GAMG_OPTIONS if method == "gamg" else {"ksp_type": "preonly", "pc_type": "lu",
                                                  "pc_factor_mat_solver_type": "mumps"}
for key, value in options.items():
    opts[key] = value
A = assemble_matrix(tangent, bcs=bcs)
A.assemble()
if method == "gamg":
    A.setNearNullSpace(rigid_body_near_null_space(V))
ksp.setOperators(A)
ksp.setFromOptions()
b = assemble_vector(residual)
correction = fem.Function(V)
newton, linear_iterations, t_solves, t_assembly = 0, 0, 0.0, 0.0
t_path = time.perf_counter()
for factor in LOAD_FACTORS:
    # The end's new position as an increment applied through the Dirichlet rows of the first
    # Newton step (lifting), so that the iterate never leaves the admissible set afterwards.
    turn(factor * ANGLE)
    first = None
    for step in range(50):
        t0 = time.perf_counter()
        A.zeroEntries()
        assemble_matrix(A, tangent, bcs=bcs)
        A.assemble()
        with b.localForm() as local:
            local.set(0.0)
        assemble_vector(b, residual)
        # Newton: K du = -R with du = (turned - u) on the Dirichlet DoFs.
        apply_lifting(b, [tangent], bcs=[bcs], x0=[u.vector], scale=-1.0)
        b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
        set_bc(b, bcs, u.vector, -1.0)
        b.scale(-1.0)
        t1 = time.perf_counter()
        norm = b.norm()
        first = first or norm
        if norm <= 1e-9 * first and step > 0:
            t_assembly += t1 - t0
            break
        ksp.solve(b, correction.vector)
        correction.x.scatter_forward()
        u.x.array[:] += correction.x.array
        t_solves += time.perf_counter() - t1
        t_assembly += t1 - t0
        linear_iterations += ksp.getIterationNumber()
        newton += 1
    else:
        raise RuntimeError("Newton did not converge at load factor %g" % factor)
t_end = time.perf_counter()

# Reaction moment about y at the turned end: the residual's nodal forces (without conditions) at the
# end's DoFs, about the centre at the deformed positions.
with b.localForm() as local:
    local.set(0.0)
assemble_vector(b, residual)
b.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
index_map = V.dofmap.index_map
n_local = index_map.size_local
coords = V.tabulate_dof_coordinates()
owned_right = right[right < n_local]
forces = b.array.reshape(-1, 3)[owned_right]
positions = coords[owned_right] + u.x.array.reshape(-1, 3)[owned_right] - CENTRE
moment_y = comm.allreduce(float(np.sum(positions[:, 2] * forces[:, 0] - positions[:, 0] * forces[:, 2])), op=MPI.SUM)
hit = np.where(np.linalg.norm(coords[:n_local] - np.array([10.0, 2.5, 0.5]), axis=1) < 1e-8)[0]
local = u.x.array[3 * hit[0] + 2] if len(hit) else 0.0
deflection = comm.allreduce(local, op=MPI.SUM) / max(comm.allreduce(len(hit), op=MPI.SUM), 1)
memory = comm.allreduce(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0, op=MPI.MAX)
if comm.rank == 0:
    print(json.dumps({"dofs": index_map.size_global * 3, "moment_y": moment_y, "qoi": moment_y,
                      "deflection": deflection, "newton": newton, "iterations": newton, "linear_iterations": linear_iterations, "assembly_s": t_assembly,
                      "solve_s": t_solves, "path_s": t_end - t_path, "memory_mb": memory,
                      "in_process_s": t_end - t_start}))
