"""What the FEniCSx peer scripts share: CG + GAMG options as in the dolfinx elasticity demo, the
six rigid-body modes of a 3D vector space as GAMG's near null space, and the timed linear-elastic
solve that reports its strain energy (dolfinx 0.5)."""
import json
import resource
import time

import numpy as np
import ufl
from dolfinx import fem, la
from dolfinx.fem.petsc import LinearProblem
from mpi4py import MPI
from petsc4py import PETSc

# Relative tolerance 1e-10 like ours; Chebyshev-Jacobi smoothing with CG eigenvalue estimates.
GAMG_OPTIONS = {"ksp_type": "cg", "ksp_rtol": 1e-10, "pc_type": "gamg", "mg_levels_ksp_type": "chebyshev",
                "mg_levels_pc_type": "jacobi", "mg_levels_esteig_ksp_type": "cg",
                "mg_levels_ksp_chebyshev_esteig_steps": 20}


def rigid_body_near_null_space(V):
    """Translations and rotations of V's nodes, orthonormalized, as a PETSc near null space."""
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
    return PETSc.NullSpace().create(vectors=modes)


def solve_and_report_energy(V, E, nu, bcs):
    """Isotropic linear elasticity on V with the Dirichlet conditions bcs and no load, by CG + GAMG
    with rigid-body modes; prints one JSON line on rank 0: DoFs, strain energy (the QoI), solve
    time, iterations and the largest rank's peak memory."""
    domain = V.mesh
    comm = domain.comm
    mu, lmbda = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))

    def eps(w):
        return ufl.sym(ufl.grad(w))

    def sigma(w):
        return 2 * mu * eps(w) + lmbda * ufl.tr(eps(w)) * ufl.Identity(3)

    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)
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


def solve_clamped_plane_stress(domain, degree, E, nu, x_clamped, x_loaded, traction):
    """Plane stress on a 2D mesh, Lagrange `degree`, clamped on the line x = x_clamped, a uniform
    traction (tx, ty) on the line x = x_loaded; MUMPS. Returns the displacement and the measure ds
    of which ds(1) is the loaded edge."""
    from dolfinx import mesh
    mu = E / (2 * (1 + nu))
    lmbda = 2 * mu * nu / (1 - nu)  # plane stress: 2 lambda mu / (lambda + 2 mu)
    V = fem.VectorFunctionSpace(domain, ("Lagrange", degree))
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)

    def sigma(w):
        eps = ufl.sym(ufl.grad(w))
        return 2 * mu * eps + lmbda * ufl.tr(eps) * ufl.Identity(2)

    facets = mesh.locate_entities_boundary(domain, 1, lambda p: np.isclose(p[0], x_loaded))
    tags = mesh.meshtags(domain, 1, facets, np.full(len(facets), 1, dtype=np.int32))
    ds = ufl.Measure("ds", domain=domain, subdomain_data=tags)
    load = fem.Constant(domain, PETSc.ScalarType(traction))
    clamped = fem.locate_dofs_geometrical(V, lambda p: np.isclose(p[0], x_clamped))
    bc = fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), clamped, V)
    problem = LinearProblem(ufl.inner(sigma(u), ufl.grad(v)) * ufl.dx, ufl.inner(load, v) * ds(1),
                            bcs=[bc], petsc_options={"ksp_type": "preonly", "pc_type": "lu",
                                                     "pc_factor_mat_solver_type": "mumps"})
    return problem.solve(), ds
