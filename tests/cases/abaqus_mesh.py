#!/usr/bin/python3
"""Abaqus/CalculiX .inp meshes (issue 14, item 8): the same mesh read from a .inp file and from
gmsh gives the same answer, and set names are the case vocabulary.

1. gmsh's own .inp export of cantilever_3d.geo (element sets: what gmsh writes for physical
   groups, lower-dimensional elements for the boundaries) against the .geo: tip displacement equal
   to 1e-9, and the quadratic export (C3D20 corner nodes) the same.
2. A CalculiX-style 2D file written here: 8-node quadrilaterals (CPS8), the clamp a node set made
   by GENERATE, the loaded edge a *SURFACE of element faces S2 over an element set, two body
   element sets with their own materials (*SOLID SECTION), lower-case keywords, comments, and the *MATERIAL/*STEP
   blocks a CalculiX deck carries; against cantilever_2d.geo with the same cells.
3. Bad files: an unsupported element, a missing node, a bad coordinate, an undefined set; each
   exit code 2 with a message naming the file, the line and what was expected.
"""
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))
sys.path.insert(0, os.path.join(root, "postproc"))
from study import mpi_env, run_case, solver_path  # noqa: E402
from case_checks import check, finish  # noqa: E402

scratch = tempfile.mkdtemp(prefix="compliant-inp-")


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def case_for_mesh(case, mesh):
    """The case with its mesh replaced: a .inp declares no geometry parameters, so its own
    Geometry/Parameters block goes (and the closed-form checks that read them)."""
    text, kept, skipping = open(case).read().splitlines(), [], False
    for line in text:
        if line.strip().startswith("subsection Parameters"):
            skipping = True
        elif skipping and line.strip() == "end":
            skipping = False
        elif not skipping:
            kept.append("  set Mesh file = " + mesh if line.strip().startswith("set Mesh file") else line)
    path = os.path.join(scratch, os.path.basename(mesh) + ".prm")
    open(path, "w").write("\n".join(kept) + "\n")
    return path


# 1. gmsh's export of the 3D cantilever, first and second order.
case_3d = os.path.join(root, "cases", "verification", "cantilever_3d.prm")
no_comparison = ["Comparison/Checks="]
reference = run_case(case_3d, no_comparison)["quantities"]
for order in (1, 2):
    inp = os.path.join(scratch, "cantilever_3d_order%d.inp" % order)
    subprocess.run(["gmsh", "-3", "-order", str(order), os.path.join(root, "meshes", "cantilever_3d.geo"),
                    "-string", "Mesh.SecondOrderIncomplete=1;", "-o", inp],
                   check=True, capture_output=True)
    q = run_case(case_for_mesh(case_3d, inp), no_comparison)["quantities"]
    print("order %d export: tip z %.12g (geo %.12g), %d cells" % (order, q["displacement_tip_y"],
                                                                 reference["displacement_tip_y"], q["n_cells"]))
    check(q["n_cells"] == reference["n_cells"], "gmsh .inp export (order %d): same cells as the .geo" % order)
    check(relative(q["displacement_tip_y"], reference["displacement_tip_y"]) < 1e-9,
          "gmsh .inp export (order %d): same tip displacement as the .geo to 1e-9" % order)

# 2. A CalculiX-style 2D deck, 40 x 4 CPS8 cells over 100 x 10 (cantilever_2d.geo, ny = 4).
nx, ny, L, H = 40, 4, 100.0, 10.0
columns = 2 * nx + 1


def node(I, J):
    return 1 + I + J * columns


lines = ["*HEADING", "cantilever written by tests/cases/abaqus_mesh.py", "** nodes on a (2nx+1) x (2ny+1) grid",
         "*node, nset=all_nodes"]
for J in range(2 * ny + 1):
    for I in range(columns):
        lines.append("%d, %.17g, %.17g" % (node(I, J), I * L / (2 * nx), -H / 2 + J * H / (2 * ny)))
lines.append("*Element, type=CPS8, elset=all_cells")
right_cells = []
for j in range(ny):
    for i in range(nx):
        I, J = 2 * i, 2 * j
        corners = [node(I, J), node(I + 2, J), node(I + 2, J + 2), node(I, J + 2)]
        mids = [node(I + 1, J), node(I + 2, J + 1), node(I + 1, J + 2), node(I, J + 1)]
        number = 1 + i + j * nx
        # Eight nodes over two lines, as decks wrap long element lines.
        lines.append("%d, %s," % (number, ", ".join(map(str, corners))))
        lines.append(", ".join(map(str, mids)))
        if i == nx - 1:
            right_cells.append(number)
lines += ["*NSET, NSET=left, GENERATE", "1, %d, %d" % (node(0, 2 * ny), columns),
          "*ELSET, ELSET=tip_cells", ", ".join(map(str, right_cells)) + ",",
          "*ELSET, ELSET=root_half"] + \
         [", ".join(str(1 + i + j * nx) for i in range(nx // 2)) for j in range(ny)] + \
         ["*ELSET, ELSET=tip_half"] + \
         [", ".join(str(1 + i + j * nx) for i in range(nx // 2, nx)) for j in range(ny)] + \
         ["*SURFACE, NAME=right, TYPE=ELEMENT", "tip_cells, S2",
          "*MATERIAL, NAME=STEEL", "*ELASTIC", "200000, 0.3",
          "*SOLID SECTION, ELSET=root_half, MATERIAL=STEEL", "1.", "*SOLID SECTION, ELSET=tip_half, MATERIAL=STEEL", "1.",
          "*STEP", "*STATIC", "*BOUNDARY", "left, 1, 2, 0.",
          "*END STEP"]
deck = os.path.join(scratch, "cantilever_2d.inp")
open(deck, "w").write("\n".join(lines) + "\n")
case_2d = os.path.join(root, "cases", "verification", "cantilever_2d.prm")
reference_2d = run_case(case_2d, no_comparison + ["Geometry/Parameters/ny=4"])["quantities"]
q = run_case(case_for_mesh(case_2d, deck), no_comparison + ["Material/Materials=root_half: steel, E=200000, nu=0.3; tip_half: steel, E=200000, nu=0.3"])["quantities"]
print("CalculiX-style deck: mean right y %.12g (geo %.12g), tip y %.12g (geo %.12g)" % (
    q["mean_displacement_right_y"], reference_2d["mean_displacement_right_y"], q["displacement_tip_y"],
    reference_2d["displacement_tip_y"]))
check(q["n_cells"] == nx * ny, "CalculiX-style deck: 160 cells")
check(relative(q["mean_displacement_right_y"], reference_2d["mean_displacement_right_y"]) < 1e-9,
      "node set clamp, element-face surface load, two body sets: same as the .geo to 1e-9")

# 3. Bad decks: exit 2, one message naming the file, the line and what was expected.
bad = {
    "wedge.inp": ("*NODE\n1, 0, 0, 0\n*ELEMENT, TYPE=C3D6\n1, 1, 1, 1, 1, 1, 1\n", ["wedge.inp", "line 3", "C3D6"]),
    "missing_node.inp": ("*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n",
                         ["missing_node.inp", "line 6", "node 4"]),
    "bad_coordinate.inp": ("*NODE\n1, 0, 0\n2, 1, zero\n", ["bad_coordinate.inp", "line 3", "zero"]),
    "undefined_set.inp": ("*NODE\n1, 0, 0\n2, 1, 0\n3, 1, 1\n4, 0, 1\n*ELEMENT, TYPE=CPS4\n1, 1, 2, 3, 4\n"
                          "*SURFACE, NAME=s\nnowhere, S1\n", ["undefined_set.inp", "nowhere"]),
}
for name, (text, words) in bad.items():
    path = os.path.join(scratch, name)
    open(path, "w").write(text)
    out = os.path.join(scratch, "out-" + name)
    p = subprocess.run(["mpirun", "-np", "2", solver_path(), case_for_mesh(case_2d, path),
                        "--set", "Comparison/Checks=", "--set", "Output/Directory=" + out],
                       capture_output=True, text=True, env=mpi_env(), timeout=120)
    text_out = p.stdout + p.stderr
    print(name + ": exit %d: %s" % (p.returncode, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""))
    check(p.returncode == 2, name + ": exit code 2")
    check(all(w in text_out for w in words), name + ": message names " + ", ".join(words))
    check("Stacktrace" not in text_out and not os.path.exists(out), name + ": no stack dump, nothing written")

finish()
