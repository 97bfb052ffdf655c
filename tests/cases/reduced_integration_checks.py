#!/usr/bin/python3
"""Discretization/Integration = reduced (issue 30, item 1): the stiffness of Q_p integrated with p
Gauss points per direction plus e = Hourglass stiffness times the fully integrated one.

    reduced_integration_checks.py SOLVER SOURCE_ROOT

References (none from this option):
- the 3D cantilever of cases/benchmarks/cantilever.prm (10 x 1 x 1, E = 1000, nu = 0.3, unit body
  load, clamped): tip deflection 15.0228845, Richardson on our fully integrated Q2 at n = 4, 8, 16
  (cantilever_speed.md; the n = 4, 6, 8 triple gives 15.02263, so +- 2e-5 relative);
- the thin leaf in torsion of cases/benchmarks/leaf_torsion.prm: strain energy 0.00537340799
  (Richardson on our uniform Q4 at m = 4, 6, 8, up to 5.1M DoFs; +- 1e-4 relative);
- finite strain: the cantilever of cases/verification/elastica_tip_load.prm (L = 100, H = 1, dead
  tip load alpha = 1) against the Euler elastica (Bisshopp and Drucker), which the continuum
  departs from by +7e-5 (converged: 30.174142 against 30.172077).
Checks: the README's errors at n = 2 and m = 2 (reduced against full on the same cells) and of the
elastica on 10 x 1 cells (10 : 1), the matrix-free p-multigrid and MUMPS on the same reduced
stiffness agree (the operator and the assembled matrix integrate alike; also the finite-strain
tangent, on the TPU strip of cases/benchmarks/flexure_finite_strain.prm), the top-fibre stress at
mid-span against beam theory (where the stabilized hourglass modes show), and the refusals.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

from case_checks import check, finish, readme_figure

solver, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
sys.path.insert(0, os.path.join(root, "postproc"))
os.environ["COMPLIANT_SOLVER"] = solver
from study import run_case  # noqa: E402
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
CANTILEVER = os.path.join(root, "cases", "benchmarks", "cantilever.prm")
ELASTICA = os.path.join(root, "cases", "verification", "elastica_tip_load.prm")
STRIP = os.path.join(root, "cases", "benchmarks", "flexure_finite_strain.prm")
LEAF = os.path.join(root, "cases", "benchmarks", "leaf_torsion.prm")
TIP, ENERGY = 15.0228845, 0.00537340799
work = tempfile.mkdtemp(prefix="compliant-reduced-")
REDUCED = ["Discretization/Integration=reduced"]


def run(case, sets):
    """The run's quantities, with its solver and integration settings beside them."""
    summary = run_case(case, sets)
    summary["quantities"]["solver"] = summary["settings"].get("solver")
    summary["quantities"]["integration"] = summary["settings"].get("integration")
    return summary["quantities"]


try:
    beam = ["Geometry/Parameters/ny=2", "Geometry/Parameters/nz=2",
            "Quantities/Stress points=top: 5 0 0.5"]
    full = run(CANTILEVER, beam + ["Linear solver/Method=direct"])
    direct = run(CANTILEVER, beam + REDUCED + ["Linear solver/Method=direct"])
    matrix_free = run(CANTILEVER, beam + REDUCED + ["Linear solver/Method=matrix-free"])
    tip_full, tip = -full["displacement_tip_z"] / TIP - 1, -direct["displacement_tip_z"] / TIP - 1
    readme_figure(tip_full, "-3.3e-3", "cantilever n = 2, full integration: error of the tip")
    readme_figure(tip, "-2.6e-4", "cantilever n = 2, reduced: error of the tip")
    check(direct["integration"].startswith("reduced, hourglass stiffness 0.03") and full["integration"] == "full",
          "the summary says the integration (%s; %s)" % (direct["integration"], full["integration"]))
    # The same reduced stiffness assembled (MUMPS) and applied matrix-free (p-multigrid CG to 1e-10),
    # at degree 2 and 3 (the p-point kernels are compiled per degree).
    q3 = beam + REDUCED + ["Discretization/Element degree=3"]
    for degree, (a, b) in ((2, (matrix_free, direct)),
                           (3, (run(CANTILEVER, q3 + ["Linear solver/Method=matrix-free"]),
                                run(CANTILEVER, q3 + ["Linear solver/Method=direct"])))):
        gap = abs(a["displacement_tip_z"] / b["displacement_tip_z"] - 1)
        check(a["solver"] == "matrix-free" and b["solver"].startswith("direct") and gap < 1e-9,
              "cantilever n = 2, Q%d reduced: matrix-free (%s) and MUMPS (%s) tips agree to %.1e (< 1e-9)"
              % (degree, a["solver"], b["solver"], gap))
    # Beam theory at mid-span: M = q (L - x)^2 / 2 = 12.5, sigma = M (h/2) / I = 75 (3D: within 1 %);
    # the recovered (projected) stress and the raw one from the displacement gradient at the point.
    readme_figure(full["stress_top_xx"] / 75 - 1, "-5.2e-3", "top fibre at mid-span, full, recovered, against 75")
    readme_figure(direct["stress_top_xx"] / 75 - 1, "2.5e-2", "top fibre at mid-span, reduced, recovered")
    readme_figure(direct["stress_top_xx_raw"] / 75 - 1, "2.9e-2", "top fibre at mid-span, reduced, raw")

    leaf_mesh = ["Geometry/Parameters/nx=10", "Geometry/Parameters/ny=20", "Geometry/Parameters/nz=2"]
    leaf = run(LEAF, leaf_mesh + REDUCED)
    readme_figure(leaf["strain_energy"] / ENERGY - 1, "3.4e-3", "leaf m = 2, reduced: error of the energy")
    check(leaf["solver_iterations"] <= 60, "leaf m = 2, reduced: %d p-multigrid iterations (full: 34)"
          % leaf["solver_iterations"])

    # Finite strain: the residual with the union rule (discretization/reduced_integration.h), the
    # matrix-free tangent with both Gauss rules. The elastica on cells 10 times longer than thick,
    # where the fully integrated Q2 is too stiff in bending under the varying moment.
    coarse = ["Geometry/Parameters/nx=10", "Geometry/Parameters/ny=1"]
    for sets, figure, label in (([], "-1.58", "full"), (REDUCED, "-0.094", "reduced")):
        q = run(ELASTICA, coarse + sets)
        readme_figure(100 * (q["displacement_tip_y"] / 30.172077 - 1), figure,
                      "elastica alpha = 1, 10 x 1 cells, %s: error of the tip deflection in %%" % label)
    strip = ["Geometry/Parameters/nx=20", "Geometry/Parameters/ny=4", "Geometry/Parameters/nz=2"] + REDUCED
    a = run(STRIP, strip + ["Linear solver/Method=matrix-free"])
    b = run(STRIP, strip + ["Linear solver/Method=direct"])
    gap = abs(a["reaction_moment_right_y"] / b["reaction_moment_right_y"] - 1)
    check(a["integration"].startswith("reduced") and gap < 1e-8,
          "TPU strip, finite strain, reduced: matrix-free (%s) and MUMPS (%s) end moments agree to %.1e (< 1e-8, "
          "Newton's tolerance)" % (a["solver"], b["solver"], gap))

    for sets, words in ((["Analysis=modal"], "for linear and nonlinear static analyses"),
                        (["Discretization/Element degree=1"], "Element degree 2 to 4"),
                        (["Discretization/Hourglass stiffness=0"], "Hourglass stiffness")):
        out = os.path.join(work, "refused")
        p = subprocess.run(["mpirun", "-np", "2", solver, CANTILEVER, "--check", "--set", "Output/Directory=" + out] +
                           sum([["--set", s] for s in REDUCED + sets], []), capture_output=True, text=True, env=ENV)
        text = p.stdout + p.stderr
        check(p.returncode == 2 and words in text and "Discretization/" in text and not os.path.exists(out),
              "%s refused with a message naming Discretization/ (exit %s)" % (" ".join(sets), p.returncode))
    out = os.path.join(work, "refused")
    p = subprocess.run(["mpirun", "-np", "2", solver, ELASTICA, "--check", "--set", "Output/Directory=" + out,
                        "--set", "Finite strain/Formulation=mixed"] + sum([["--set", s] for s in REDUCED], []),
                       capture_output=True, text=True, env=ENV)
    text = p.stdout + p.stderr
    check(p.returncode == 2 and "Finite strain/Formulation = mixed" in text and "Discretization/" in text
          and not os.path.exists(out), "finite-strain mixed u-p with reduced integration refused (exit %s)" % p.returncode)
    # A paired model (Target/Paired model) set to reduced integration: the ladder would run it.
    paired_dir = os.path.join(work, "paired")
    os.makedirs(paired_dir)
    for name in ("flexure_hinge_3d.prm", "flexure_hinge.prm"):
        text = open(os.path.join(root, "cases", name)).read()
        text = re.sub(r"set Mesh file = (\S+\.geo)", lambda m: "set Mesh file = " + os.path.join(root, "meshes", m.group(1)), text)
        if name == "flexure_hinge.prm":
            text += "\nsubsection Discretization\n  set Integration = reduced\nend\n"
        open(os.path.join(paired_dir, name), "w").write(text)
    p = subprocess.run(["mpirun", "-np", "2", solver, os.path.join(paired_dir, "flexure_hinge_3d.prm"), "--check"],
                       capture_output=True, text=True, env=ENV, cwd=paired_dir)
    text = p.stdout + p.stderr
    check(p.returncode == 2 and "Target/Paired model" in text and "Integration = reduced" in text,
          "a paired model with Integration = reduced refused (exit %s)" % p.returncode)
finally:
    shutil.rmtree(work, ignore_errors=True)
finish()
