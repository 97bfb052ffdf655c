#!/usr/bin/python3
"""Field files keep every tensor component (issue: deal.II 9.4 wrote stress and strain to HDF5/XDMF as
dim-component vectors, losing yy in 2D and yy, zz, yz in 3D). The patch tests' linear fields give a
uniform strain, so every node of fields.h5 must hold the exact strain, stress (Hooke's law of the
case's E = 1e6, nu = 0.25), principal stresses and von Mises, to float32 round-off:

- 3D: u = 1e-3 (2x + y + z)/2, ... so eps = 1e-3 [[1, .5, .5], [.5, 1, .5], [.5, .5, 1]];
- 2D plane stress: u = 1e-3 (x + y/2), v = 1e-3 (y + x/2), so eps = 1e-3 [[1, .5], [.5, 1]], sigma_zz = 0.
"""
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish  # noqa: E402

here = os.path.dirname(os.path.abspath(__file__))
E, nu = 1e6, 0.25


def expected(eps, plane_stress):
    dim = eps.shape[0]
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    if plane_stress:
        lam = 2 * lam * mu / (lam + 2 * mu)
    sigma = lam * np.trace(eps) * np.eye(dim) + 2 * mu * eps
    full = np.zeros((3, 3))
    full[:dim, :dim] = sigma
    principal = sorted(np.linalg.eigvalsh(full), reverse=True)
    s = full
    vm = np.sqrt(0.5 * ((s[0, 0] - s[1, 1]) ** 2 + (s[1, 1] - s[2, 2]) ** 2 + (s[2, 2] - s[0, 0]) ** 2)
                 + 3 * (s[0, 1] ** 2 + s[0, 2] ** 2 + s[1, 2] ** 2))
    axes = "xyz"
    values = {}
    for i in range(dim):
        for j in range(i, dim):
            values["strain_%s%s" % (axes[i], axes[j])] = eps[i, j]
            values["stress_%s%s" % (axes[i], axes[j])] = sigma[i, j]
    if dim == 2:
        values["stress_zz"] = 0.0
    values.update(stress_1=principal[0], stress_2=principal[1], stress_3=principal[2], von_mises=vm)
    return values


cases = [("3D", "patch_test_3d.prm", 1e-3 * np.array([[1, .5, .5], [.5, 1, .5], [.5, .5, 1]]), False),
         ("2D plane stress", "patch_test_2d.prm", 1e-3 * np.array([[1, .5], [.5, 1]]), True)]
for name, case, eps, plane_stress in cases:
    out = tempfile.mkdtemp(prefix="fields-")
    proc = subprocess.run(["mpirun", "-np", "2", solver_path(), os.path.join(here, case), "--set",
                           "Output/Directory=" + out, "--set", "Output/Fields=true"],
                          capture_output=True, text=True, env=mpi_env())
    check(proc.returncode == 0, "%s: run exit %d" % (name, proc.returncode))
    with h5py.File(os.path.join(out, "fields.h5"), "r") as f:
        for key, value in expected(eps, plane_stress).items():
            if key not in f:
                check(False, "%s: %s missing from fields.h5 (%s)" % (name, key, sorted(f.keys())))
                continue
            data = np.array(f[key]).ravel()
            scale = max(abs(value), 1e-3 * E * 1e-3 if key.startswith("stress") or key == "von_mises" else 1e-3)
            worst = np.max(np.abs(data - value)) / scale
            check(worst < 1e-6, "%s: %s = %.6g at all %d nodes (worst relative deviation %.1e)"
                  % (name, key, value, data.size, worst))
    xdmf = open(os.path.join(out, "fields.xdmf")).read()
    check('Attribute Name="stress_yy"' in xdmf and 'Attribute Name="stress_1"' in xdmf,
          "%s: fields.xdmf names the components for ParaView" % name)
    subprocess.run(["rm", "-rf", out])

finish()
