#!/usr/bin/python3
"""The command line as a user meets it: --help documents every parameter (generated from the
code), --check validates without output, --set overrides, and each kind of bad input gives a
message naming the file/parameter, a non-zero exit and no output folder."""
import os
import subprocess
import tempfile
import time
from case_checks import check, finish

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.join(here, "..", "..")
solver = os.environ["COMPLIANT_SOLVER"]
case = os.path.join(root, "cases", "flexure_hinge.prm")


def run(args, np=2):
    cmd = ["mpirun", "-np", str(np), solver] + args
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    return p.returncode, p.stdout, p.stderr


rc, out, err = run(["--help"], np=1)
check(rc == 0 and "Total force" in out and "prbm_pivot_stiffness" in out and "semiflex" in out,
      "--help lists parameters, closed forms and materials")
rc, out, err = run([case, "--help"], np=1)
check(rc == 0 and "set l " in out and "flexure length" in out, "--help with a case lists the .geo parameters with their help")
rc, out, err = run([case, "--check"])
check(rc == 0 and "is valid" in out, "--check accepts the default case")


def bad(name, args, must_contain, extra_file=None):
    out_dir = tempfile.mkdtemp(prefix="compliant-bad-")
    os.rmdir(out_dir)
    rc, out, err = run(args + ["--set", "Output/Directory=" + out_dir])
    ok = rc != 0 and all(m in err for m in must_contain) and not os.path.exists(out_dir)
    check(ok, "%s: exit %d, message names %s, no output" % (name, rc, must_contain))
    if not ok:
        print(err[-1500:])


def write_case(text):
    f = tempfile.NamedTemporaryFile("w", suffix=".prm", delete=False, dir=os.path.join(root, "cases"))
    f.write(text)
    f.close()
    return f.name


with open(case) as f:
    base = f.read()
misspelled = write_case(base.replace("set Clamped = base", "set Clampd = base"))
try:
    bad("misspelled parameter", [misspelled], [os.path.basename(misspelled), "Clampd", "Line"])
finally:
    os.remove(misspelled)
bad("bad value", [case, "--set", "Discretization/Element degree=7"], ["Element degree"])
bad("unknown boundary name", [case, "--set", "Boundary conditions/Clamped=bse"], ["bse", "base", "drive"])
bad("unknown body name", [case, "--set", "Material/Materials=bdy: steel"], ["bdy", "body"])
bad("unknown material", [case, "--set", "Material/Materials=*: unobtainium"], ["unobtainium", "semiflex"])
bad("unknown geometry parameter", [case, "--set", "Geometry/Parameters/length=3"], ["length"])
bad("load expression with a syntax error", [case, "--set", "Loads/Traction=drive: 0 -1/(x-"], ["Loads/Traction", "flexure_hinge.prm"])
bad("load expression that is NaN", [case, "--set", "Loads/Traction=drive: 0 1/(x-x)"], ["not finite", "Loads/Traction", "flexure_hinge.prm"])
bad("geometry gmsh cannot mesh", [case, "--set", "Geometry/Parameters/l=0"], ["flexure_hinge_2d.geo", "gmsh could not", "geometry parameters"])
bad("refinement beyond memory", [case, "--set", "Discretization/Global refinements=8", "--set", "Geometry/Parameters/nt=8"],
    ["Global refinements = 8", "GB available"])
bad("missing mesh file", [case, "--set", "Geometry/Mesh file=nothing.geo"], ["nothing.geo"])
bad("unknown closed form", [case, "--set", "Comparison/Checks=rotational_stiffness_drive ~ prbm_pivot(E=E)"], ["prbm_pivot", "Comparison/Checks"])

# Output/Directory that is a file: refused at once on every rank (it used to hang after the solve).
blocker = tempfile.NamedTemporaryFile("w", delete=False)
blocker.write("keep")
blocker.close()
for target in (blocker.name, os.path.join(blocker.name, "sub")):
    start = time.time()
    rc, out, err = run([case, "--set", "Output/Directory=" + target])
    check(rc == 2 and "Output/Directory" in err and "not a directory" in err and time.time() - start < 60
          and open(blocker.name).read() == "keep",
          "output directory %s: exit %d in %.1f s, message names Output/Directory" % (target, rc, time.time() - start))
os.remove(blocker.name)
bad("bad expression", [case, "--set", "Boundary conditions/Rotation=drive: degrees=1, center=q/2 0"], ["center", "q/2"])
bad("point outside the mesh", [case, "--set", "Quantities/Points=far: 1000 0"], ["far", "outside"])
bad("plane stress with the mixed formulation", [case, "--set", "Analysis=nonlinear static", "--set", "Model=plane stress",
    "--set", "Finite strain/Formulation=mixed"], ["Formulation", "plane stress"])
bad("follower pressure on an unknown boundary", [case, "--set", "Analysis=nonlinear static",
    "--set", "Finite strain/Follower pressure=nowhere: 1"], ["Follower pressure", "nowhere"])
bad("missing case file", [os.path.join(root, "cases", "no_such_case.prm")], ["no_such_case.prm"])
finish()
