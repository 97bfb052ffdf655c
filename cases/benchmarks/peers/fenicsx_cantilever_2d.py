#!/usr/bin/python3
"""FEniCSx (dolfinx 0.5, Debian's python3-dolfinx): the plane-stress cantilever of
cases/verification/cantilever_2d.prm, an independent reference for the tests (issue 34). L x H
(y from -H/2 to H/2), E = 200000, nu = 0.3, clamped at x = 0, a total force -1 spread evenly over
x = L; the mean vertical displacement of that edge (integral over the edge / H). Lagrange degree
p on (ny L/H) x ny square quadrilaterals, MUMPS. Prints one JSON line per mesh (rank 0).
Run: mpirun -np 1 /usr/bin/python3 fenicsx_cantilever_2d.py L H p NY [NY ...]"""
import json
import sys

import numpy as np
import ufl
from dolfinx import fem, mesh
from dolfinx.fem.petsc import LinearProblem
from mpi4py import MPI
from petsc4py import PETSc

comm = MPI.COMM_WORLD
L, H, degree = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3])
E, nu = 200000.0, 0.3
mu = E / (2 * (1 + nu))
lmbda = 2 * mu * nu / (1 - nu)  # plane stress


def solve(ny):
    nx = int(round(ny * L / H))
    domain = mesh.create_rectangle(comm, [np.array([0.0, -H / 2]), np.array([L, H / 2])], [nx, ny],
                                   mesh.CellType.quadrilateral)
    V = fem.VectorFunctionSpace(domain, ("Lagrange", degree))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)

    def sigma(w):
        eps = ufl.sym(ufl.grad(w))
        return 2 * mu * eps + lmbda * ufl.tr(eps) * ufl.Identity(2)

    facets = mesh.locate_entities_boundary(domain, 1, lambda p: np.isclose(p[0], L))
    tags = mesh.meshtags(domain, 1, facets, np.full(len(facets), 1, dtype=np.int32))
    ds = ufl.Measure("ds", domain=domain, subdomain_data=tags)
    traction = fem.Constant(domain, PETSc.ScalarType((0.0, -1.0 / H)))
    clamped = fem.locate_dofs_geometrical(V, lambda p: np.isclose(p[0], 0.0))
    bc = fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), clamped, V)
    problem = LinearProblem(ufl.inner(sigma(u), ufl.grad(v)) * ufl.dx, ufl.inner(traction, v) * ds(1),
                            bcs=[bc], petsc_options={"ksp_type": "preonly", "pc_type": "lu",
                                                     "pc_factor_mat_solver_type": "mumps"})
    uh = problem.solve()
    mean = comm.allreduce(fem.assemble_scalar(fem.form(uh[1] * ds(1))), op=MPI.SUM) / H
    return V.dofmap.index_map.size_global * 2, mean


for ny in [int(a) for a in sys.argv[4:]]:
    dofs, mean = solve(ny)
    if comm.rank == 0:
        print(json.dumps({"ny": ny, "degree": degree, "dofs": dofs, "mean_displacement_right_y": mean}), flush=True)
