#!/usr/bin/python3
"""Every shipped .geo checks its parameters (issue 33, item 3): one bad value per file (the likely
mistake: a thickness that is not positive or does not fit in its part, a zero cell count) makes
`--check` end with exit code 2 within 10 s and a message holding the .geo's own Error text (the
file name and the condition it needs), with no stack dump and no output directory left behind;
the default parameters pass `--check` (exit 0).

    geo_parameters.py SOLVER SOURCE_ROOT

The cases are minimal: the mesh file (absolute path) and the model; Analysis = modal needs no
supports (free-free), so one case fits every geometry. The section_*.geo files are for the
cross-section tool: they run through section_torsion --check ($SECTION_TORSION, default: next to
the solver in section/), or, without it, through the gmsh command line. A .geo with parameters
but no entry in BAD below fails the test.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from case_checks import check, finish

if len(sys.argv) != 3:
    sys.exit("usage: geo_parameters.py SOLVER SOURCE_ROOT")
solver, root = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
meshes = os.path.join(root, "meshes")
section_tool = os.environ.get("SECTION_TORSION", os.path.join(os.path.dirname(solver), "section", "section_torsion"))
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
DUMP_SIGNS = ("Segmentation", "Stacktrace", "terminate called", "Aborted", "core dumped", "MPI_ABORT was invoked")
SECONDS = 10

# One bad value per file and the words of the condition it breaks (part of the file's Error text).
# Model: "3d" for the 3D geometries, "plane stress" for the 2D ones; "section" for section_torsion.
BAD = {
    "arch_2d": ("plane stress", "t=0", "0 < t < 2 R"),
    "cantilever_2d": ("plane stress", "ny=0", "ny >= 1"),
    "cantilever_3d": ("3d", "W=0", "L, H, W > 0"),
    "compliant_pivot_arm": ("plane stress", "W=2", "W > t (1 + 2 rf)"),
    "contact_blocks": ("plane stress", "ny=0", "nl, nu, ny, nzl, nzu >= 1"),
    "cook_membrane": ("plane stress", "n=0", "n >= 1"),
    "cook_membrane_3d": ("3d", "t=0", "t > 0"),
    "cosine_beam_2d": ("plane stress", "t=-1", "t > 0"),
    "cosine_double_beam_2d": ("plane stress", "t=8", "0 < t < g"),
    "elliptical_hole_2d": ("plane stress", "nc=5", "nc >= 2 even"),
    "elliptical_hole_3d": ("3d", "t=0", "a, b, t > 0"),
    "flap_mechanism": ("plane stress", "lk=12", "lk + 2 rf t below the crank and rocker lengths"),
    "flexure_hinge_2d": ("plane stress", "t=10", "0 < t < T"),
    "flexure_hinge_3d": ("3d", "t=0", "0 < t < T"),
    "flexure_hinge_pin_2d": ("plane stress", "yp=5", "the pin clear of the link (yp - rp > T/2)"),
    "fork_2d": ("plane stress", "g=0", "L, h, g, a > 0"),
    "hertz_cylinder_2d": ("plane stress", "nb=0", "nb >= 1"),
    "hertz_block_3d": ("3d", "m=0", "m >= 1"),
    "hertz_two_cylinders_2d": ("plane stress", "nb=0", "nb >= 1"),
    "jansen_leg": ("plane stress", "rp=15", "0 < rp < w/2"),
    "leaf_coupling": ("3d", "b=0", "L, a, b > 0"),
    "leaf_spring": ("3d", "nb=0", "nb >= 1"),
    "patch_test": ("plane stress", "extrude=-0.05", "extrude >= 0"),
    "pinned_bar_2d": ("plane stress", "rp=10", "0 < rp < w/2"),
    "plate_3d": ("3d", "nz=0", "nx, ny, nz >= 1"),
    "plate_circular_hole_2d": ("plane stress", "a=6", "0 < a < W, a < H"),
    "plate_quarter_3d": ("3d", "t=0", "a, b, t > 0"),
    "section_angle": ("section", "t=40", "0 < t < b1"),
    "section_channel": ("section", "r=50", "0 <= r < bf - tw"),
    "section_i_beam": ("section", "tf=100", "0 < tf < h/2"),
    "section_rectangle": ("section", "n=0", "n >= 1"),
    "section_triangle": ("section", "a=0", "a > 0"),
    "section_tube": ("section", "r=10", "0 < r < R"),
    "spline_notch_2d": ("plane stress", "d=3", "0 < d < H"),
    "spline_profile_2d": ("plane stress", "d=1", "0 <= d < h/2"),
    "thick_cylinder_2d": ("plane stress", "b=5", "0 < a < b"),
    "thick_cylinder_3d": ("3d", "nz=0", "nz >= 1"),
    "thick_sphere_3d": ("3d", "a=20", "0 < a < b"),
}

scratch = tempfile.mkdtemp(prefix="compliant-geo-parameters-")


def error_text(geo):
    """The file's first Error("...") text up to its first format directive (%g: a value)."""
    with open(geo) as f:
        m = re.search(r'Error\("([^"]*)"', f.read())
    return m.group(1).split("%")[0] if m else None


def write_case(name, model):
    path = os.path.join(scratch, name + ".prm")
    with open(path, "w") as f:
        if model != "section":
            f.write("set Analysis = modal\nset Model = %s\n" % model)
        f.write("subsection Geometry\n  set Mesh file = %s\nend\n" % os.path.join(meshes, name + ".geo"))
    return path


def run(name, model, extra):
    """Runs --check on the minimal case of one .geo with extra --set arguments; returns exit code,
    text, seconds and whether an output directory was left behind."""
    out = os.path.join(scratch, "out-" + name)
    case = write_case(name, model)
    if model == "section":
        cmd = [section_tool, case]
    else:
        cmd = ["mpirun", "-np", "2", solver, case]
    cmd += ["--check", "--set", "Output/Directory=" + out]
    for s in extra:
        cmd += ["--set", "Geometry/Parameters/" + s]
    start = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=120, env=env, cwd=scratch)
        code, text = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        code, text = None, "(no exit within 120 s)"
    seconds = time.time() - start
    left = os.path.exists(out) or os.path.exists(os.path.join(scratch, "results"))
    return code, text, seconds, left


def run_gmsh(name, extra):
    """The gmsh command line instead of section_torsion: 2D mesh of the .geo."""
    cmd = ["gmsh", "-2", os.path.join(meshes, name + ".geo"), "-o", os.path.join(scratch, name + ".msh")]
    for s in extra:
        cmd += ["-setnumber"] + s.split("=", 1)
    start = time.time()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=scratch)
        code, text = p.returncode, p.stdout + p.stderr
    except subprocess.TimeoutExpired:
        code, text = None, "(no exit within 120 s)"
    return code, text, time.time() - start, False


def last_lines(text, n=4):
    """The error lines of a run (else its last lines): mpirun's own report after them says nothing."""
    lines = [l for l in text.strip().splitlines() if "rror" in l] or text.strip().splitlines()[-n:]
    return "\n      " + "\n      ".join(lines[:n])


check(os.path.isfile(solver) and os.access(solver, os.X_OK), "solver %s is there" % solver)
use_section_tool = os.path.isfile(section_tool) and os.access(section_tool, os.X_OK)
print("section_*.geo through %s" % (section_tool if use_section_tool else "the gmsh command line (no section_torsion)"))

with_parameters = sorted(os.path.basename(g)[:-4] for g in glob.glob(os.path.join(meshes, "*.geo"))
                         if "DefineConstant" in open(g).read())
check(with_parameters == sorted(BAD), "every .geo with parameters has a bad value here (missing: %s, no such file: %s)"
      % (sorted(set(with_parameters) - set(BAD)), sorted(set(BAD) - set(with_parameters))))

try:
    for name in with_parameters:
        if name not in BAD:
            continue
        model, bad, condition = BAD[name]
        geo = os.path.join(meshes, name + ".geo")
        text_in_file = error_text(geo)
        if not check(text_in_file is not None and condition in text_in_file and text_in_file.startswith(name + ".geo: "),
                     "%s.geo has an Error(\"%s.geo: ...\") naming '%s'" % (name, name, condition)):
            continue
        runner = (lambda extra: run(name, model, extra)) if model != "section" or use_section_tool else \
            (lambda extra: run_gmsh(name, extra))

        code, text, seconds, left = runner([])
        says_valid = "is valid" in text or (model == "section" and not use_section_tool)  # gmsh says nothing
        ok = code == 0 and says_valid and not left
        check(ok, "%s: default parameters pass (exit %s in %.1f s)%s" % (name, code, seconds, "" if ok else last_lines(text)))

        code, text, seconds, left = runner([bad])
        bad_code = 2 if model != "section" or use_section_tool else 1  # the gmsh command line exits 1
        dumped = [d for d in DUMP_SIGNS if d in text]
        ok = code == bad_code and seconds < SECONDS and text_in_file in text and not dumped and not left
        detail = "%s: %s gives exit %s (want %d) in %.1f s, message holds the Error text" % (name, bad, code, bad_code, seconds)
        if text_in_file not in text:
            detail += "; MISSING '%s'" % text_in_file
        if dumped:
            detail += "; dump: %s" % dumped
        if left:
            detail += "; output directory left behind"
        if not ok:
            detail += last_lines(text)
        check(ok, detail)
finally:
    shutil.rmtree(scratch, ignore_errors=True)
finish()
