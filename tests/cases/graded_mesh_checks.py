#!/usr/bin/python3
"""Meshes graded along x (meshes/graded_layers.geo through cantilever_3d.geo's grade_x and
graded_ends; issue 30, item 1).

    graded_mesh_checks.py SOLVER SOURCE_ROOT

- The grid lines gmsh makes equal those the peers' decks are written on
  (cases/benchmarks/peers/calculix_common.py graded), for both ends, the start and the far end, to
  1e-9 of the length: the benchmark compares the codes on one mesh.
- The thin leaf in torsion of cases/benchmarks/leaf_torsion.prm at m = 2 (10 x 20 x 2 Q2 cells,
  12.9k DoFs), uniform and graded 50 toward both ends: the strain energy against 0.00537340799
  (Richardson on our uniform Q4 at m = 4, 6, 8 with up to 5.1M DoFs; the graded Q3 ladder's
  m = 4, 5, 6 lie within 1.6e-5 of it, so its uncertainty is ~1e-4 of the energy). Graded, the
  error is the README's 3.1e-3 (measured 3.09e-3); uniform on the same DoFs 2.9e-2 (2.95e-2).
- A grading below 1 is refused by --check with the .geo's message and exit code 2.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from case_checks import check, finish, readme_figure

solver, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
sys.path.insert(0, os.path.join(root, "cases", "benchmarks", "peers"))
from calculix_common import graded  # noqa: E402
sys.path.insert(0, os.path.join(root, "postproc"))
os.environ["COMPLIANT_SOLVER"] = solver
from study import run_case  # noqa: E402

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
GEO = os.path.join(root, "meshes", "cantilever_3d.geo")
LEAF = os.path.join(root, "cases", "benchmarks", "leaf_torsion.prm")
REFERENCE = 0.00537340799
work = tempfile.mkdtemp(prefix="compliant-graded-")


def gmsh_x_lines(nx, grade, ends):
    """The distinct x coordinates of the vertices gmsh makes from cantilever_3d.geo (first order)."""
    out = os.path.join(work, "mesh.msh")
    subprocess.run(["gmsh", "-3", GEO, "-format", "msh22", "-o", out, "-setnumber", "L", "40", "-setnumber", "H", "10",
                    "-setnumber", "W", "1", "-setnumber", "nx", str(nx), "-setnumber", "ny", "2",
                    "-setnumber", "nz", "1", "-setnumber", "grade_x", repr(grade), "-setnumber", "graded_ends",
                    str(ends)], check=True, capture_output=True)
    text = open(out).read()
    nodes = text.split("$Nodes")[1].split("$EndNodes")[0].strip().splitlines()[1:]
    return sorted({round(float(line.split()[1]), 9) for line in nodes})


def leaf_energy(grade):
    q = run_case(LEAF, ["Geometry/Parameters/%s=%s" % (name, value) for name, value in
                        (("nx", 10), ("ny", 20), ("nz", 2), ("grade_x", grade), ("graded_ends", 0))])["quantities"]
    return q["strain_energy"], q["n_dofs"]


try:
    for nx, grade, ends in ((10, 50, 0), (9, 16, 0), (7, 20, 1), (7, 20, 2)):
        ours = gmsh_x_lines(nx, grade, ends)
        peers = graded(0.0, 40.0, nx, grade, ends)
        gap = max(abs(a - b) for a, b in zip(ours, peers)) if len(ours) == len(peers) else float("inf")
        lengths = [b - a for a, b in zip(peers, peers[1:])]
        check(gap < 1e-9 * 40 and abs(max(lengths) / min(lengths) / grade - 1) < 1e-9,
              "nx = %d, grade %g, ends %d: gmsh's grid lines are the peers' (largest gap %.1e), longest over "
              "shortest cell %.6g" % (nx, grade, ends, gap, max(lengths) / min(lengths)))

    uniform, dofs_uniform = leaf_energy(1)
    graded_50, dofs_graded = leaf_energy(50)
    check(dofs_uniform == dofs_graded == 12915, "leaf m = 2: %d and %d DoFs" % (dofs_uniform, dofs_graded))
    readme_figure((graded_50 - REFERENCE) / REFERENCE, "3.1e-3", "leaf m = 2 graded 50, error of the energy")
    readme_figure((uniform - REFERENCE) / REFERENCE, "2.9e-2", "leaf m = 2 uniform, error of the energy")

    bad = subprocess.run(["mpirun", "-np", "2", solver, LEAF, "--check", "--set", "Output/Directory=" +
                          os.path.join(work, "bad"), "--set", "Geometry/Parameters/grade_x=0.5"],
                         capture_output=True, text=True, env=ENV)
    text = bad.stdout + bad.stderr
    check(bad.returncode == 2 and "grade_x >= 1" in text and "cantilever_3d.geo" in text and
          not re.search("Segmentation|Stacktrace|terminate called", text) and
          not os.path.exists(os.path.join(work, "bad")),
          "grade_x = 0.5 refused with the .geo's message, exit code %s" % bad.returncode)
finally:
    shutil.rmtree(work, ignore_errors=True)
finish()
