#!/usr/bin/python3
"""A corpus of hostile inputs (issue 15): every run on 2 ranks under a timeout must end with the
expected exit code, one message that names the file/parameter and what was expected (each entry
lists words the message must hold), no stack dump or abort, no hang, and no output directory left
behind when it fails. Inputs that are unusual but valid (CRLF line endings, a UTF-8 BOM) must work.

    hostile_inputs.py            # the whole corpus; prints one line per input and a count by outcome

The corpus is counted by kind, and the counts must be the README's (section "Running cases"):
a test added or removed without the README changing fails here.
"""
import os
import shutil
import subprocess
import sys
import tempfile
import threading
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))
build = os.environ.get("COMPLIANT_BUILD", os.path.join(root, "build"))
solver = os.environ.get("COMPLIANT_SOLVER", os.path.join(build, "solver", "fe", "compliant"))
tools = {"fatigue_life": os.path.join(build, "solver", "fatigue", "fatigue_life"),
         "jansen_kinematics": os.path.join(build, "solver", "mechanisms", "jansen", "jansen_kinematics"),
         "flap_prbm": os.path.join(build, "solver", "mechanisms", "four_bar", "flap_prbm")}
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
hinge = os.path.join(root, "cases", "flexure_hinge.prm")
cantilever_3d = os.path.join(root, "cases", "verification", "cantilever_3d.prm")
modal = os.path.join(root, "cases", "verification", "modal_cantilever_3d.prm")
scratch = tempfile.mkdtemp(prefix="compliant-hostile-")
outcomes = {}
failed = []
# The README's census of the corpus: 135 inputs.
README_CENSUS = {"refused with exit 2": 123, "tool errors with exit 1": 6, "must work": 5, "rank failing alone": 1}
census = {}
KIND = {0: "must work", 1: "tool errors with exit 1", 2: "refused with exit 2"}
DUMP_SIGNS = ("Stacktrace", "terminate called", "Aborted", "Segmentation", "core dumped",
              "An error occurred in line", "MPI_ABORT was invoked",
              # the expression library's own text: an error is said once, in our words
              "Message: <", "Formula:", "Token:", "Errc:")


def scratch_file(name, content, mode="w"):
    path = os.path.join(scratch, name)
    with open(path, mode) as f:
        f.write(content)
    return path


def record(name, ok, detail):
    outcomes.setdefault("passed" if ok else "FAILED", []).append(name)
    print(("PASS  " if ok else "FAIL  ") + name + ": " + detail)
    if not ok:
        failed.append(name)


def tree_resident_bytes(root_pid):
    """The resident memory of a process and all its descendants (ranks, gmsh's child), summed."""
    parents = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open("/proc/%s/stat" % entry) as f:
                    parents[int(entry)] = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                pass
    tree, grew = {root_pid}, True
    while grew:
        more = {pid for pid, parent in parents.items() if parent in tree} - tree
        tree |= more
        grew = bool(more)
    total = 0
    for pid in tree:
        try:
            with open("/proc/%d/statm" % pid) as f:
                total += int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")
        except (OSError, IndexError, ValueError):
            pass
    return total


def run_sampled(cmd, timeout):
    """Runs cmd, sampling the resident memory of its process tree every 20 ms (GNU time's %M misses
    ranks that mpirun does not reap when it aborts the job). Returns (returncode, stdout, stderr,
    peak bytes), or None on a time-out."""
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    result = {}
    reader = threading.Thread(target=lambda: result.update(zip(("out", "err"), p.communicate())))
    reader.start()
    start, peak = time.time(), 0
    while reader.is_alive():
        peak = max(peak, tree_resident_bytes(p.pid))
        reader.join(0.02)
        if time.time() - start > timeout:
            p.kill()
            reader.join()
            return None
    return p.returncode, result["out"], result["err"], peak


def solver_case(name, args, words, code=2, np=2, timeout=120, bounds=None):
    """The solver on a case with --set overrides; fails with `code` and a message holding `words`.
    bounds = (seconds, GB): the run must also end within the seconds, its processes (ranks, gmsh's
    child) together resident below the GB, sampled every 20 ms."""
    given = [a.split("=", 1)[1] for a in args if a.startswith("Output/Directory=")]
    out = given[0] if given else os.path.join(scratch, "out-" + str(len(outcomes.get("passed", [])) + len(failed)))
    cmd = ["mpirun", "-np", str(np), solver] + args + ([] if given else ["--set", "Output/Directory=" + out])
    census[KIND[code]] = census.get(KIND[code], 0) + 1
    start = time.time()
    if bounds:
        sampled = run_sampled(cmd, timeout)
        if sampled is None:
            record(name, False, "hung (no exit within %d s)" % timeout)
            return
        returncode, stdout, stderr, peak = sampled
    else:
        try:
            p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            record(name, False, "hung (no exit within %d s)" % timeout)
            return
        returncode, stdout, stderr = p.returncode, p.stdout, p.stderr
    seconds = time.time() - start
    text = stdout + stderr
    missing = [w for w in words if w.lower() not in text.lower()]
    dumped = [d for d in DUMP_SIGNS if d in text]
    left = os.path.exists(out) and code != 0
    ok = returncode == code and not missing and not dumped and not left
    detail = "exit %d (want %d) in %.1f s" % (returncode, code, seconds)
    if bounds:
        ok = ok and seconds < bounds[0] and peak < bounds[1] * 1e9
        detail += ", peak %.2f GB (bounds %g s, %g GB)" % (peak / 1e9, bounds[0], bounds[1])
    if missing:
        detail += ", message lacks %s" % missing
    if dumped:
        detail += ", dump: %s" % dumped
    if left:
        detail += ", output directory left behind"
    if not ok:
        detail += "\n      " + "\n      ".join(stderr.strip().splitlines()[-6:])
    record(name, ok, detail)


def tool(name, program, args, words, code=2):
    """A standalone tool run in an empty folder: it must leave nothing there when it fails."""
    census[KIND[code]] = census.get(KIND[code], 0) + 1
    cwd = tempfile.mkdtemp(dir=scratch)
    try:
        p = subprocess.run([tools[program]] + args, capture_output=True, text=True, timeout=60, cwd=cwd)
    except subprocess.TimeoutExpired:
        record(name, False, "hung")
        return
    text = p.stdout + p.stderr
    missing = [w for w in words if w.lower() not in text.lower()]
    dumped = [d for d in DUMP_SIGNS if d in text]
    left = [os.path.join(d, f) for d, _, files in os.walk(cwd) for f in files]
    ok = p.returncode == code and not missing and not dumped and not left
    detail = "exit %d (want %d)" % (p.returncode, code)
    if left:
        detail += ", left behind: %s" % left
    if missing:
        detail += ", message lacks %s: %s" % (missing, p.stderr.strip()[-300:])
    record(name, ok, detail)


with open(hinge) as f:
    base = f.read()
S = "--set"

# --- the case file itself -------------------------------------------------------------------
solver_case("empty case file", [scratch_file("empty.prm", "")], ["empty.prm"])
solver_case("binary garbage", [scratch_file("garbage.prm", bytes(range(256)) * 8, "wb")], ["garbage.prm"])
solver_case("misspelled section", [scratch_file("section.prm", base.replace("subsection Material", "subsection Materal"))],
            ["section.prm", "Materal"])
solver_case("misspelled parameter", [scratch_file("param.prm", base.replace("set Clamped = base", "set Clampd = base"))],
            ["param.prm", "Clampd"])
# Found by fuzzing the case reader: deal.II does not check a value starting with '{' against its
# pattern, and reading it as a number then failed with a stack dump.
solver_case("geometry parameter in braces", [scratch_file("brace.prm", base.replace("set t = 1", "set t = {1"))],
            ["brace.prm", "line", "t", "{"])
solver_case("element degree in braces", [scratch_file("brace2.prm", base.replace("set Element degree = 2", "set Element degree = {2"))],
            ["brace2.prm", "Element degree", "{"])
# Found by fuzzing the case reader: a NUL in the mesh file name (the C library stops at it, gmsh
# does not) sent gmsh into endless recursive merging; names gmsh would guess a format for, too.
solver_case("NUL in the mesh file name", [scratch_file("nul.prm", "set Model = plane stress\nsubsection Geometry\n"
                                                      "  set Mesh file = cantilever_2d.geo\x00\x02\nend\n")],
            ["nul.prm", "Mesh file", "control character"])
solver_case("mesh file neither .geo nor .msh", [hinge, "--set", "Geometry/Mesh file=" + hinge],
            ["Mesh file", ".geo", ".msh"])
solver_case("unterminated subsection", [scratch_file("open.prm", base + "\nsubsection Loads\n")], ["open.prm"])
# Valid inputs are checked for more than their exit code: --check must say the case is valid, and
# read the same mesh as the plain file (140 cells, 1314 DoFs for cases/flexure_hinge.prm).
solver_case("CRLF line endings work", [scratch_file("crlf.prm", base.replace("\n", "\r\n")), "--check"],
            ["is valid", "140 cells, 1314 DoFs"], code=0)
solver_case("UTF-8 BOM works", [scratch_file("bom.prm", "\ufeff" + base), "--check"], ["is valid", "140 cells, 1314 DoFs"], code=0)
# A target on a model without load: the rungs are all zero, and adaptive refinement flagged no cell
# (it ended on an internal message, exit 1).
solver_case("target on an unloaded model", [hinge, S, "Boundary conditions/Rotation=", S, "Target/Relative error=1",
                                             S, "Target/Refinement=adaptive", S, "Target/Quantities=strain_energy"],
            ["flexure_hinge.prm", "no load", "Target"])
solver_case("missing case file", [os.path.join(scratch, "absent.prm")], ["absent.prm"])
solver_case("directory as case file", [scratch], [scratch])
solver_case("--set without its section", [hinge, S, "Materials=*: steel"], ["Materials"])
solver_case("--set without a value", [hinge, S, "Analysis"], ["Analysis"])

# --- enums and numbers ------------------------------------------------------------------------
solver_case("unknown analysis", [hinge, S, "Analysis=dynamic"], ["Analysis", "dynamic"])
solver_case("unknown model", [hinge, S, "Model=4d"], ["Model", "4d"])
solver_case("unknown solver method", [hinge, S, "Linear solver/Method=magic"], ["Method", "magic"])
solver_case("element degree 0", [hinge, S, "Discretization/Element degree=0"], ["Element degree"])
solver_case("element degree 7", [hinge, S, "Discretization/Element degree=7"], ["Element degree"])
solver_case("negative refinements", [hinge, S, "Discretization/Global refinements=-1"], ["Global refinements"])
solver_case("refinement beyond the allowed range", [hinge, S, "Discretization/Global refinements=9"], ["Global refinements", "0...8"])
solver_case("refinement beyond memory", [hinge, S, "Discretization/Global refinements=8", S, "Geometry/Parameters/nt=8"],
            ["Global refinements", "GB"])
solver_case("E = 0", [hinge, S, "Material/Materials=*: steel, E=0"], ["E"])
solver_case("E < 0", [hinge, S, "Material/Materials=*: steel, E=-200e3"], ["E"])
solver_case("E = nan", [hinge, S, "Material/Materials=*: steel, E=nan"], ["E"])
solver_case("E = inf", [hinge, S, "Material/Materials=*: steel, E=inf"], ["E"])
solver_case("nu = 0.5", [hinge, S, "Material/Materials=*: steel, nu=0.5"], ["nu"])
solver_case("nu = -1.5", [hinge, S, "Material/Materials=*: steel, nu=-1.5"], ["nu"])
solver_case("negative density", [hinge, S, "Material/Materials=*: steel, density=-1"], ["density"])
solver_case("thickness 0", [hinge, S, "Material/Thickness=0"], ["Thickness"])
solver_case("geometry parameter nan", [hinge, S, "Geometry/Parameters/t=nan"], ["t"])
solver_case("geometry parameter negative", [hinge, S, "Geometry/Parameters/t=-1"], ["must be positive"])
solver_case("geometry gmsh cannot build", [hinge, S, "Geometry/Parameters/l=0"], ["flexure_hinge_2d.geo", "gmsh"])
solver_case("rotation angle nan", [hinge, S, "Boundary conditions/Rotation=drive: degrees=nan, center=l/2 0"], ["Rotation"])
solver_case("traction inf", [hinge, S, "Loads/Traction=drive: 0 inf"], ["Traction"])
# Rigid boundaries (Boundary conditions/Rigid): touching a support, malformed, infinite, wrong analysis.
rigid_case = os.path.join(root, "cases", "verification", "rigid_end_moment.prm")
solver_case("rigid boundary touching the clamp", [rigid_case, S, "Boundary conditions/Rigid=top: moment=1"],
            ["Rigid", "top", "shares nodes"])
solver_case("rigid moment with two numbers in 2D", [rigid_case, S, "Boundary conditions/Rigid=right: moment=1 2"],
            ["Rigid", "moment", "one number"])
solver_case("rigid force infinite", [rigid_case, S, "Boundary conditions/Rigid=right: force=0 1/0"],
            ["Rigid", "finite"])
solver_case("rigid unknown field", [rigid_case, S, "Boundary conditions/Rigid=right: torque=1"],
            ["Rigid", "torque", "expected moment"])
solver_case("rigid boundary in a modal analysis", [rigid_case, S, "Analysis=modal"], ["Rigid", "modal"])
solver_case("nonlinear, no supports, only a rigid moment", [rigid_case, S, "Analysis=nonlinear static", S,
            "Boundary conditions/Clamped="], ["Boundary conditions", "constrained"])
solver_case("ladder: closed form with a negative length", [os.path.join(root, "cases", "verification", "cantilever_2d.prm"),
            S, "Target/Relative error=0.5", S,
            "Comparison/Checks=mean_displacement_right_y ~ euler_bernoulli_cantilever_deflection(P=-1, L=-5, E=E, b=thickness, h=H)"],
            ["Comparison/Checks", "'L'", "positive"])
solver_case("traction syntax error", [hinge, S, "Loads/Traction=drive: 0 -1/(x-"], ["Traction", "-1/(x-", "position"])
solver_case("traction NaN expression", [hinge, S, "Loads/Traction=drive: 0 1/(x-x)"], ["Traction", "not finite"])
solver_case("traction with one component", [hinge, S, "Loads/Traction=drive: 1"], ["Traction"])
solver_case("pressure syntax error", [hinge, S, "Loads/Pressure=drive: 2*(x-"], ["Pressure", "drive", "2*(x-", "position"])
solver_case("pressure on an unknown boundary", [hinge, S, "Loads/Pressure=lid: 1"], ["Pressure", "lid"])
solver_case("pressure given twice", [hinge, S, "Loads/Pressure=drive: 1; drive: 2"], ["Pressure", "twice"])
solver_case("pressure at finite strain", [hinge, S, "Analysis=nonlinear static", S, "Loads/Pressure=drive: 1"],
            ["Pressure", "Follower pressure"])
solver_case("point with nan coordinate", [hinge, S, "Quantities/Points=p: nan 0"], ["p"])
solver_case("point outside the mesh", [hinge, S, "Quantities/Points=far: 1000 0"], ["far", "outside"])
solver_case("stress point outside the mesh", [hinge, S, "Quantities/Stress points=far: 1000 0"],
            ["Stress points", "far", "outside"])
solver_case("stress point with one coordinate", [hinge, S, "Quantities/Stress points=p: 1"],
            ["Stress points", "coordinates"])
solver_case("target error negative", [hinge, S, "Target/Relative error=-1"], ["Relative error"])
solver_case("modal: 0 modes", [modal, S, "Modal/Number of modes=0"], ["modes"])
solver_case("mixed formulation in plane stress", [hinge, S, "Discretization/Formulation=mixed"],
            ["Formulation", "plane stress"])
# nu = 0: the u-p pressure equation ln J = p / lambda has lambda = 0 (it failed at every step with
# "the residual is not finite").
solver_case("mixed finite strain with nu = 0",
            [os.path.join(root, "cases", "verification", "elastica_tip_load.prm"), S, "Finite strain/Formulation=mixed"],
            ["Formulation", "nu = 0", "lambda > 0"])
solver_case("mixed formulation in a linkage analysis",
            [os.path.join(root, "cases", "jansen", "leg_structure.prm"), S, "Discretization/Formulation=mixed"],
            ["Formulation", "linkage"])
solver_case("mixed formulation at degree 1", [cantilever_3d, S, "Discretization/Formulation=mixed", S,
                                              "Discretization/Element degree=1"], ["Formulation", "degree"])
solver_case("modal on a distributed mesh", [modal, S, "Discretization/Mesh partition=distributed"],
            ["Mesh partition", "modal", "shared"])
solver_case("unknown mesh partition", [hinge, S, "Discretization/Mesh partition=scattered"],
            ["Mesh partition", "scattered"])
solver_case("adaptive ladder on a distributed mesh",
            [hinge, S, "Target/Relative error=0.01", S, "Target/Refinement=adaptive", S,
             "Discretization/Mesh partition=distributed"], ["Mesh partition", "adaptive"])
solver_case("point outside a distributed mesh",
            [hinge, S, "Discretization/Mesh partition=distributed", S, "Quantities/Points=far: 1000 0"],
            ["far", "outside"])
solver_case("modal: -3 modes", [modal, S, "Modal/Number of modes=-3"], ["modes"])
solver_case("negative load step", [hinge, S, "Analysis=nonlinear static", S, "Finite strain/Initial step=-0.1"],
            ["Initial step"])

# --- meshing: geometry parameters a .geo cannot build (issue 33) --------------------------------
# Each shipped .geo checks its parameters and stops with its own message (the file and the
# condition) before gmsh builds anything; --check stops right after meshing.
def meshing_case(name, case, setting, words):
    solver_case("meshing: " + name, [os.path.join(root, "cases", case), "--check", S,
                                     "Geometry/Parameters/" + setting], words)


meshing_case("flexure as thick as its links", "flexure_hinge.prm", "t=10", ["flexure_hinge_2d.geo", "0 < t < T"])
meshing_case("no cells through the flexure", "flexure_hinge.prm", "nt=0", ["flexure_hinge_2d.geo", "nt >= 1"])
meshing_case("3D hinge of zero width", "flexure_hinge_3d.prm", "b=0", ["flexure_hinge_3d.geo", "b > 0"])
meshing_case("column of zero length", "verification/column_imperfection.prm", "L=0", ["cantilever_2d.geo", "L > 0"])
meshing_case("3D strip of zero width", "verification/rollup_rigid_moment_3d.prm", "W=0", ["cantilever_3d.geo", "W > 0"])
meshing_case("fillet wider than the pivot's arm", "morphing_wing/compliant_pivot.prm", "rf=100",
             ["compliant_pivot_arm.geo", "W > t (1 + 2 rf)"])
meshing_case("negative fillet in the flap", "flap/flap_fe.prm", "rf=-1", ["flap_mechanism.geo", "rf >= 0"])
meshing_case("bistable beams overlapping", "bistable/double_beam.prm", "t=100",
             ["cosine_double_beam_2d.geo", "must not overlap"])
meshing_case("Jansen links that cannot meet", "jansen/leg_structure_3d.prm", "BC=1",
             ["jansen_leg.geo", "cannot be assembled"])
meshing_case("leaves of the coupling overlapping", "leaf_spring/coupling.prm", "r=1",
             ["leaf_coupling.geo", "r > (a + b)/2"])
meshing_case("leaf of zero aspect", "leaf_spring/leaf_bending.prm", "aspect=0", ["leaf_spring.geo", "aspect > 0"])
meshing_case("cylinder bore outside its outer radius", "verification/lame_cylinder.prm", "a=1000",
             ["thick_cylinder_2d.geo", "0 < a < b"])
meshing_case("sphere with zero mesh size", "verification/lame_sphere.prm", "lc=0", ["thick_sphere_3d.geo", "lc > 0"])
meshing_case("plate of zero thickness", "verification/plate_buckling.prm", "t=0", ["plate_quarter_3d.geo", "t > 0"])
meshing_case("flat arch", "verification/arch_snap_through.prm", "h=0", ["arch_2d.geo", "0 < h"])
meshing_case("pin eye wider than the bar", "verification/pinned_bar.prm", "rp=100", ["pinned_bar_2d.geo", "rp < w/2"])
meshing_case("Cook's membrane with no cells", "verification/cook_membrane_neo_hooke.prm", "n=0",
             ["cook_membrane.geo", "n >= 1"])
# A self-intersecting outline: gmsh cannot mesh it and says where.
bowtie = scratch_file("bowtie.geo", "Point(1) = {0, 0, 0, 0.2}; Point(2) = {4, 4, 0, 0.2}; Point(3) = {4, 0, 0, 0.2};\n"
                      "Point(4) = {0, 4, 0, 0.2}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
                      "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                      "Physical Curve(\"left\") = {4}; Physical Surface(\"body\") = {1};\n")
solver_case("meshing: self-intersecting outline",
            [scratch_file("bowtie.prm", "set Model = plane stress\nset Analysis = modal\nsubsection Geometry\n"
                          "  set Mesh file = " + bowtie + "\nend\n"), "--check"], ["bowtie.geo", "gmsh could not mesh"])

# --- meshing that crashes, hangs or asks for too many cells (issue 33) --------------------------
# gmsh runs in a child process under a memory cap and a time limit, and the cell count is estimated
# from the curve meshes before the surfaces are meshed: each of these ends with exit 2 on every rank
# and one message naming the .geo and its parameters, within 10 s, no process above 2 GB.
bounds = (10, 2)
solver_case("meshing: flexure 1e-9 thick (gmsh crashes)", [hinge, S, "Geometry/Parameters/t=1e-9"],
            ["flexure_hinge_2d.geo", "t=1e-09", "gmsh crashed"], bounds=bounds)
solver_case("meshing: flexure 1e-6 thick (1e8 cells)", [hinge, S, "Geometry/Parameters/t=1e-6"],
            ["flexure_hinge_2d.geo", "t=1e-06", "cells", "Maximum cells"], bounds=bounds)
solver_case("meshing: flexure 1e-6 thick on 1 rank", [hinge, S, "Geometry/Parameters/t=1e-6"],
            ["flexure_hinge_2d.geo", "t=1e-06", "cells", "Maximum cells"], np=1, bounds=bounds)
solver_case("meshing: more cells than Geometry/Maximum cells", [hinge, S, "Geometry/Maximum cells=100"],
            ["flexure_hinge_2d.geo", "t=1", "more than the 100 allowed", "Maximum cells"], bounds=bounds)
# A study's points file (compliant --points, postproc/study.py's batches): unreadable, or a line
# whose override has no '='.
solver_case("points file missing", [hinge, "--points", os.path.join(scratch, "no_such_points.txt")],
            ["--points", "cannot read", "no_such_points.txt"])
solver_case("points file with an override without '='",
            [hinge, "--points", scratch_file("points.txt", os.path.join(scratch, "p0") + "\tGeometry/Parameters/t\n")],
            ["--points", "points.txt", "line 1", "Geometry/Parameters/t"])
solver_case("meshing: Geometry/Maximum cells raised lets the hinge through",
            [hinge, S, "Geometry/Maximum cells=100000000", "--check"], ["is valid", "140 cells, 1314 DoFs"], code=0)
# A .geo whose parameter sends gmsh's parser into a loop of 1e12 passes (a hang), and one whose
# parser list outgrows the memory cap of reading (1 GB): the child is stopped, the run refused.
square = ("Point(1) = {0, 0, 0, 0.5}; Point(2) = {1, 0, 0, 0.5}; Point(3) = {1, 1, 0, 0.5};\n"
          "Point(4) = {0, 1, 0, 0.5}; Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};\n"
          "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
          "Physical Curve(\"left\") = {4}; Physical Surface(\"body\") = {1};\n")
hang_geo = scratch_file("hang.geo", "DefineConstant[ h = {0, Name \"Parameters/h\"} ];\n" + square +
                        "If (h > 0)\n  For i In {1:1e12}\n    x = i;\n  EndFor\nEndIf\n")
hang_case = scratch_file("hang.prm", "set Model = plane stress\nset Analysis = modal\nsubsection Geometry\n"
                         "  set Mesh file = " + hang_geo + "\nend\n")
solver_case("meshing: gmsh hangs", [hang_case, S, "Geometry/Parameters/h=1", S, "Geometry/Meshing time limit=3",
                                    "--check"], ["hang.geo", "h=1", "did not finish within 3 s"], bounds=bounds)
forever_geo = scratch_file("forever.geo", square + "For i In {1:1e12}\n  x = i;\nEndFor\n")
solver_case("meshing: gmsh hangs reading the geometry",
            [hang_case, S, "Geometry/Mesh file=" + forever_geo, S, "Geometry/Meshing time limit=3", "--check"],
            ["forever.geo", "did not finish within 3 s"], bounds=bounds)
memory_geo = scratch_file("memory.geo", "DefineConstant[ m = {0, Name \"Parameters/m\"} ];\n" + square +
                          "If (m > 0)\n  a[] = {1:m};\nEndIf\n")
solver_case("meshing: gmsh outgrows its memory cap",
            [hang_case, S, "Geometry/Mesh file=" + memory_geo, S, "Geometry/Parameters/m=3e8", "--check"],
            ["memory.geo", "m=3e+08", "memory cap"],
            # 4.8 s alone: gmsh's parser needs that long to fill 1 GB; 20 s leaves room for a
            # suite running beside it (the 10 s bar is for its own inputs, above)
            bounds=(20, 2))

# --- names, meshes, supports -------------------------------------------------------------------
solver_case("missing mesh file", [hinge, S, "Geometry/Mesh file=nothing.geo"], ["nothing.geo"])
solver_case("unknown boundary name", [hinge, S, "Boundary conditions/Clamped=bse"], ["bse"])
solver_case("empty boundary name", [hinge, S, "Boundary conditions/Clamped=:"], ["Clamped"])
solver_case("unknown body name", [hinge, S, "Material/Materials=bdy: steel"], ["bdy"])
solver_case("unknown material", [hinge, S, "Material/Materials=*: unobtainium"], ["unobtainium"])
plain_geo = scratch_file("plain.geo", "Point(1)={0,0,0,0.5}; Point(2)={1,0,0,0.5}; Point(3)={1,1,0,0.5};"
                         " Point(4)={0,1,0,0.5}; Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,1};"
                         " Curve Loop(1)={1,2,3,4}; Plane Surface(1)={1};\n")
plain_case = scratch_file("plain.prm", "set Model = plane stress\nsubsection Geometry\n  set Mesh file = plain.geo\nend\n"
                          "subsection Material\n  set Materials = *: steel\nend\n"
                          "subsection Boundary conditions\n  set Clamped = left\nend\n")
solver_case("mesh without physical groups", [plain_case], ["plain.geo", "physical"])
bad_geo = scratch_file("broken.geo", "Point(1) = {0, 0, 0;\nLine(1) = {1, 7};\n")
solver_case("a .geo gmsh cannot read", [plain_case, S, "Geometry/Mesh file=" + bad_geo], ["broken.geo"])
# Arc-length continuation follows loads: a displacement drive is refused before anything is written.
solver_case("arc length on a displacement drive",
            [os.path.join(root, "cases", "verification", "cosine_beam_displacement.prm"), S,
             "Finite strain/Path=arc length"], ["cosine_beam_displacement.prm", "Path = arc length", "displacement"])
# Linear buckling would leave out the geometric stiffness of the forces a rigid piece carries.
solver_case("linear buckling with a rigid boundary",
            [os.path.join(root, "cases", "verification", "arch_arc_length.prm"), S, "Analysis=buckling"],
            ["arch_arc_length.prm", "Boundary conditions/Rigid", "Reference load factor"])
# Geometry/Imperfection: malformed, and on an analysis it does not shape.
column_imperfect = os.path.join(root, "cases", "verification", "column_imperfection.prm")
solver_case("imperfection without an amplitude", [column_imperfect, S, "Geometry/Imperfection=1"],
            ["column_imperfection.prm", "Geometry/Imperfection", "<mode>: <amplitude>"])
solver_case("imperfection in a linear analysis", [column_imperfect, S, "Geometry/Imperfection=1: 0.1",
            S, "Analysis=linear static"], ["Geometry/Imperfection", "linear static"])
# Contact (Contact/Obstacles): a boundary the mesh lacks, an obstacle missing a parameter or of
# an unknown kind, one drawn into the part, contact in an analysis or a path that does not solve it.
stop_case = os.path.join(root, "cases", "contact", "flexure_hinge_stop.prm")
solver_case("contact on an unknown boundary", [stop_case, S, "Contact/Boundaries=drive_tpo"],
            ["flexure_hinge_stop.prm", "Contact/Boundaries", "drive_tpo"])
solver_case("contact obstacle without its radius", [stop_case, S, "Contact/Obstacles=pin: circle, center=25 10.634"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "pin", "radius"])
solver_case("contact obstacle of an unknown kind", [stop_case, S, "Contact/Obstacles=pin: cone, center=25 10.634, radius=2"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "pin", "cone"])
solver_case("contact obstacle overlapping the part at rest",
            [stop_case, S, "Contact/Obstacles=pin: circle, center=25 5, radius=2"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "pin", "overlaps the part at rest"])
solver_case("contact in a linear analysis", [stop_case, S, "Analysis=linear static"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "linear static"])
# Pins at finite strain: the whole mesh on every rank, and not about a finite-strain state.
leg_ground = os.path.join(root, "cases", "jansen", "leg_ground_contact.prm")
solver_case("pins at finite strain on a distributed mesh", [leg_ground, S, "Discretization/Mesh partition=distributed"],
            ["leg_ground_contact.prm", "Mesh partition", "Extra constraints", "whole mesh"])
solver_case("a pin naming an unknown eye at finite strain",
            [leg_ground, S, "Extra constraints/Pins=B: pin_B, eye_AB_B, eye_BC_Q"],
            ["leg_ground_contact.prm", "Extra constraints/Pins", "eye_BC_Q"])
solver_case("pins in buckling about a finite-strain state",
            [os.path.join(root, "cases", "jansen", "leg_structure.prm"), S, "Geometry/Parameters/quads=1", S,
             "Analysis=buckling", S, "Buckling/Reference load factor=1", S, "Loads/Total force=", S,
             "Loads/Traction=foot: 0 1"],
            ["leg_structure.prm", "Extra constraints", "finite-strain state"])
solver_case("a moving obstacle on an arc-length path",
            [stop_case, S, "Finite strain/Path=arc length", S,
             "Contact/Obstacles=pin: circle, center=25 10.634, radius=2, motion=0 1"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "pin", "moves", "arc length"])
solver_case("friction on an arc-length path",
            [stop_case, S, "Finite strain/Path=arc length", S,
             "Contact/Obstacles=pin: circle, center=25 10.634, radius=2, friction=0.3"],
            ["flexure_hinge_stop.prm", "Contact/Obstacles", "pin", "friction", "arc length"])
solver_case("no supports (singular)", [cantilever_3d, S, "Boundary conditions/Clamped="], ["Boundary conditions", "constrained"])
# Mechanisms: supports that hold some rigid motions but not all (a singular matrix that a direct
# solver would turn into displacements of 1e11 without a word).
solver_case("mechanism: one component held (3D linear)",
            [cantilever_3d, S, "Boundary conditions/Clamped=", S, "Boundary conditions/Displacement=left: x=0"],
            ["cantilever_3d.prm", "Boundary conditions", "3 rigid-body motions", "translation along y",
             "translation along z", "rotation about x", "mechanism"])
solver_case("mechanism: one component held (3D finite strain)",
            [os.path.join(root, "cases", "benchmarks", "flexure_finite_strain.prm"), S, "Boundary conditions/Clamped=",
             S, "Boundary conditions/Rotation=", S, "Boundary conditions/Displacement=left: x=0", S,
             "Loads/Traction=right: 0 0 0.001"],
            ["flexure_finite_strain.prm", "Boundary conditions", "translation along y", "rotation about x", "mechanism"])
# Two boxes meshed apart (gmsh's built-in kernel merges no nodes): the loaded one holds on to nothing.
unglued = scratch_file("unglued.geo", "Geometry.AutoCoherence = 0;\n" + "\n".join(
    ["Point(%d) = {%g, %g, %g};" % (4 * b + k + 1, 5 * b, y, z) for b in (0, 1)
     for k, (y, z) in enumerate([(0, 0), (1, 0), (1, 1), (0, 1)])] +
    ["Line(%d) = {%d, %d};" % (4 * b + k + 1, 4 * b + k + 1, 4 * b + (k + 1) % 4 + 1) for b in (0, 1) for k in range(4)] +
    ["Curve Loop(%d) = {%d, %d, %d, %d}; Plane Surface(%d) = {%d};" % (b + 1, 4 * b + 1, 4 * b + 2, 4 * b + 3, 4 * b + 4, b + 1, b + 1)
     for b in (0, 1)] +
    ["Transfinite Curve{:} = 3; Transfinite Surface{1, 2}; Recombine Surface{1, 2};",
     "a[] = Extrude {5, 0, 0} { Surface{1}; Layers{4}; Recombine; };",
     "b[] = Extrude {5, 0, 0} { Surface{2}; Layers{4}; Recombine; };",
     "Physical Surface(\"left\") = {1}; Physical Surface(\"right\") = {b[0]};",
     "Physical Volume(\"body\") = {a[1], b[1]};"]) + "\n")
solver_case("mechanism: a second body glued to nothing",
            [scratch_file("unglued.prm", "set Model = 3d\nsubsection Geometry\n  set Mesh file = " + unglued +
                          "\nend\nsubsection Material\n  set Materials = *: steel\nend\n"
                          "subsection Boundary conditions\n  set Clamped = left\nend\n"
                          "subsection Loads\n  set Traction = right: 0 -1 0\nend\n")],
            ["unglued.prm", "6 rigid-body motions", "body 2 of 2", "held by nothing", "BooleanFragments"])
# The same two boxes glued by gmsh, with their shared face in a boundary group: deal.II cannot give an
# interior face a boundary id (it stopped with a stack trace); the group and the surface are named.
glued = scratch_file("glued.geo", open(unglued).read().replace("AutoCoherence = 0", "AutoCoherence = 1").replace(
    'Physical Surface("right") = {b[0]};', 'Physical Surface("right") = {b[0]}; Physical Surface("joint") = {2};'))
solver_case("a boundary group inside the body (two glued volumes' shared face)",
            [scratch_file("glued.prm", "set Model = 3d\nsubsection Geometry\n  set Mesh file = " + glued +
                          "\nend\nsubsection Material\n  set Materials = *: steel\nend\n"
                          "subsection Boundary conditions\n  set Clamped = left\nend\n")],
            ["glued.prm", "Mesh file", "boundary group 'joint'", "inside the body", "between volumes"])
# The same mistake in a plain MSH 2.2 file (two hexahedra, a physical surface on the face they
# share), which carries no topology: found from the elements themselves.
two_hex_nodes = [(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1, 2)]
number = {p: i + 1 for i, p in enumerate(two_hex_nodes)}
quad_at = lambda x: [number[(x, 0, 0)], number[(x, 1, 0)], number[(x, 1, 1)], number[(x, 0, 1)]]
hex_at = lambda x: [number[(x, 0, 0)], number[(x + 1, 0, 0)], number[(x + 1, 1, 0)], number[(x, 1, 0)],
                    number[(x, 0, 1)], number[(x + 1, 0, 1)], number[(x + 1, 1, 1)], number[(x, 1, 1)]]
two_hex_elements = [(3, 2, quad_at(0)), (3, 3, quad_at(1)), (5, 1, hex_at(0)), (5, 1, hex_at(1))]
two_hex = scratch_file("two_hex.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n3 1 \"body\"\n"
                       "2 2 \"left\"\n2 3 \"joint\"\n$EndPhysicalNames\n$Nodes\n12\n" +
                       "".join("%d %d %d %d\n" % ((number[p],) + p) for p in two_hex_nodes) +
                       "$EndNodes\n$Elements\n4\n" +
                       "".join("%d %d 2 %d %d %s\n" % (i + 1, t, g, i + 1, " ".join(map(str, n)))
                               for i, (t, g, n) in enumerate(two_hex_elements)) + "$EndElements\n")
solver_case("a boundary group inside the body in a plain MSH 2.2 file (no topology)",
            [scratch_file("two_hex.prm", "set Model = 3d\nsubsection Geometry\n  set Mesh file = " + two_hex +
                          "\nend\nsubsection Material\n  set Materials = *: steel\nend\n"
                          "subsection Boundary conditions\n  set Clamped = left\nend\n")],
            ["two_hex.prm", "Mesh file", "boundary group 'joint'", "inside the body", "shared by two cells"])
# In 2D the same by element edges: two quadrilaterals, a physical curve on the edge they share.
two_quad = scratch_file("two_quad.msh", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n2 1 \"body\"\n"
                        "1 2 \"left\"\n1 3 \"joint\"\n$EndPhysicalNames\n$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n"
                        "4 0 1 0\n5 1 1 0\n6 2 1 0\n$EndNodes\n$Elements\n4\n1 1 2 2 1 1 4\n2 1 2 3 2 2 5\n"
                        "3 3 2 1 3 1 2 5 4\n4 3 2 1 4 2 3 6 5\n$EndElements\n")
solver_case("a boundary group inside the body in a plain MSH 2.2 file, 2D (element edges)",
            [scratch_file("two_quad.prm", "set Model = plane stress\nsubsection Geometry\n  set Mesh file = " + two_quad +
                          "\nend\nsubsection Material\n  set Materials = *: steel\nend\n"
                          "subsection Boundary conditions\n  set Clamped = left\nend\n")],
            ["two_quad.prm", "Mesh file", "boundary group 'joint'", "element edges inside the body"])
solver_case("held without a clamp: some components on each of two faces",
            [cantilever_3d, S, "Boundary conditions/Clamped=", S, "Boundary conditions/Displacement=left: x=0, y=0; right: z=0",
             "--check"], ["is valid"], code=0)
solver_case("mechanism: an edge held across only (2D)",
            [os.path.join(root, "cases", "verification", "cantilever_2d.prm"), S, "Boundary conditions/Clamped=", S,
             "Boundary conditions/Displacement=left: x=0"],
            ["cantilever_2d.prm", "a rigid-body motion free", "translation along y", "mechanism"])
solver_case("unwritable output directory", [hinge, S, "Output/Directory=/proc/compliant"], ["Output/Directory"])
solver_case("one cell on more ranks than cells", [cantilever_3d, S, "Geometry/Parameters/nx=1",
            S, "Geometry/Parameters/ny=1", S, "Geometry/Parameters/nz=1", "--check"], ["is valid", "Mesh: 1 cells"], code=0, np=3)

# --- one rank fails alone --------------------------------------------------------------------
# A failure injected on rank 1 only (COMPLIANT_TEST_FAIL_RANK), while rank 0 goes on into the
# analysis and waits in a collective call: the failing rank waits 3 s for the others (an error on
# every rank is reported once by rank 0), then reports itself and aborts the job. README: the job
# ends within 3 s of the failure plus the abort. Asserted: the message, the exit within 1 s of it
# (the abort; measured 0.15 s), and the whole run at most 3 s + 2 s longer than the same run with
# --check, which stops at about the point of failure (start-up, reading, meshing): measured 3.1-3.3 s
# longer; the 2 s cover the timing noise of two runs on a shared machine.
census["rank failing alone"] = 1
start = time.time()
subprocess.run(["mpirun", "-np", "2", solver, hinge, "--check"], capture_output=True, text=True, timeout=120, env=env)
to_failure = time.time() - start
out = os.path.join(scratch, "out-rank")
start = time.time()
p = subprocess.Popen(["mpirun", "-np", "2", solver, hinge, "--set", "Output/Directory=" + out],
                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                     env=dict(env, COMPLIANT_TEST_FAIL_RANK="1"))
lines = []
reader = threading.Thread(target=lambda: lines.extend((time.time(), l) for l in p.stderr))
reader.start()
try:
    p.wait(timeout=60)
    reader.join()
    seconds = time.time() - start
    said = [t for t, l in lines if "failure injected on rank 1" in l]
    after_message = seconds - (said[0] - start) if said else float("inf")
    record("one rank fails alone", p.returncode != 0 and bool(said) and after_message < 1
           and seconds - to_failure < 5 and not os.path.exists(out),
           "exit %d in %.1f s: %.2f s after the message, %.1f s after the point of failure (--check run: %.1f s;"
           " bars 1 s and 3 + 2 s)" % (p.returncode, seconds, after_message, seconds - to_failure, to_failure))
except subprocess.TimeoutExpired:
    p.kill()
    record("one rank fails alone", False, "hung")

# --- the standalone tools ----------------------------------------------------------------------
# The standalone tools exit 1 on bad input (their own convention), with the same kind of message.
tool("fatigue_life: empty CSV", "fatigue_life", [scratch_file("empty.csv", "")], ["empty.csv", "header"], code=1)
tool("fatigue_life: malformed CSV", "fatigue_life", [scratch_file("bad.csv", "time,a\n0,0.01\n1,abc\n")],
     ["bad.csv", "line 3", "abc"], code=1)
tool("fatigue_life: NaN amplitude", "fatigue_life", [scratch_file("nan.csv", "time,a\n0,0.01\n1,nan\n2,0.02\n")],
     ["nan.csv", "finite"], code=1)
tool("fatigue_life: negative amplitude scale", "fatigue_life",
     [scratch_file("ok.csv", "time,a\n0,0.01\n1,0.02\n2,0.01\n"), "--scale", "-1"], ["scale"], code=2)
tool("fatigue_life: missing file", "fatigue_life", [os.path.join(scratch, "absent.csv")], ["absent.csv"], code=1)
tool("jansen_kinematics: zero steps", "jansen_kinematics", ["--steps", "0"], ["steps"], code=1)
tool("flap_prbm: links that cannot assemble", "flap_prbm", ["--set", "crank_length_mm=100"],
     ["cannot be closed"], code=1)

shutil.rmtree(scratch, ignore_errors=True)
total = sum(len(v) for v in outcomes.values())
print("\n%d hostile inputs: %s" % (total, ", ".join("%d %s" % (len(v), k) for k, v in outcomes.items())))
print("by kind: %s" % ", ".join("%d %s" % (v, k) for k, v in sorted(census.items())))
if census != README_CENSUS or total != sum(README_CENSUS.values()):
    print("FAIL  the corpus is not the README's: %s (%d inputs) against %s (%d)"
          % (census, total, README_CENSUS, sum(README_CENSUS.values())))
    failed.append("census")
sys.exit(1 if failed else 0)
