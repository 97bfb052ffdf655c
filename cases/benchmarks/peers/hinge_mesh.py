#!/usr/bin/python3
"""The 3D blade flexure hinge of the speed benchmark (issue 11), one structured hexahedral mesh for
all three codes, so that they solve exactly the same discrete geometry.

Geometry (E = 1000, nu = 0.3 in the cases): two blocks 10 x 6 x 5 joined by a blade of length 4, in-plane
thickness 0.5 and full width 5 (x along the hinge, y across the blade, z out of plane):
  block A: x in [0, 10],  y in [-3, 3],      z in [0, 5]   (face x = 0 clamped)
  blade:   x in [10, 14], y in [-0.25, 0.25], z in [0, 5]
  block B: x in [14, 24], y in [-3, 3],      z in [0, 5]   (face x = 24 turned rigidly by 1 degree
                                                            about the z axis through (12, 0))
Mesh level m: m cells through the blade, 2m along each block and the blade, 2m cells on each side of
the blade in y, 2m in z; blade cells 8/m x 2/m x 10/m in units of 1/4: aspect 4 : 1 : 5. Cells
44 m^3, Q2 DoFs about 1056 m^3 (m = 2: 8.5k, m = 10: 1.06M). The blade roots are re-entrant edges,
so the strain energy (the QoI: rotational stiffness 2 U / theta^2) converges below the smooth order.
GRADE > 1 grades the cells toward those edges: along x every segment toward both its ends (the blade's
roots, and the blocks' clamped and turned faces too: graded toward the roots alone, a block's far cells
grew to most of its length and stiffened it), along y in the blocks toward the blade's faces; the
longest cell of each segment GRADE times its shortest (lengths in geometric progression, as
meshes/graded_layers.geo).

    hinge_mesh.py inp M FILE [GRADE]    writes FILE: C3D8 elements, node sets clamped and turned, element
                                        set hinge
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from calculix_common import graded  # noqa: E402

LENGTH_BLOCK, LENGTH_BLADE, HALF_HEIGHT, HALF_T, WIDTH = 10.0, 4.0, 3.0, 0.25, 5.0
ANGLE_DEG, CENTER = 1.0, (12.0, 0.0)


def grid(m, grade=1.0):
    """Grid lines in x, y, z and the set of cells (i, j, k) that belong to the part."""
    def lines(segments):  # [(start, end, cells, graded end: 0 both, 1 start, 2 end, None uniform)]
        out = [segments[0][0]]
        for a, b, n, ends in segments:
            out += graded(a, b, n, grade if ends is not None else 1.0, ends or 0)[1:]
        return out
    b0, b1 = LENGTH_BLOCK, LENGTH_BLOCK + LENGTH_BLADE
    xs = lines([(0.0, b0, 2 * m, 0), (b0, b1, 2 * m, 0), (b1, b1 + LENGTH_BLOCK, 2 * m, 0)])
    ys = lines([(-HALF_HEIGHT, -HALF_T, 2 * m, 2), (-HALF_T, HALF_T, m, None), (HALF_T, HALF_HEIGHT, 2 * m, 1)])
    zs = lines([(0.0, WIDTH, 2 * m, None)])
    blade_x = range(2 * m, 4 * m)
    blade_y = range(2 * m, 3 * m)
    cells = [(i, j, k) for k in range(len(zs) - 1) for j in range(len(ys) - 1) for i in range(len(xs) - 1)
             if i not in blade_x or j in blade_y]
    return xs, ys, zs, cells


def q2_dofs(m):
    """3 x the nodes of the degree-2 (27-node) hexahedra on the level-m mesh (any grading)."""
    xs, ys, zs, cells = grid(m)
    nodes = {(2 * i + a, 2 * j + b, 2 * k + c) for i, j, k in cells for a in range(3) for b in range(3) for c in range(3)}
    return 3 * len(nodes)


def turned_displacement(x, y):
    """The exact rigid rotation of the end face about the z axis through CENTER."""
    import math
    t = math.radians(ANGLE_DEG)
    dx, dy = x - CENTER[0], y - CENTER[1]
    return dx * (math.cos(t) - 1) - dy * math.sin(t), dx * math.sin(t) + dy * (math.cos(t) - 1)


def write_inp(m, path, grade=1.0):
    xs, ys, zs, cells = grid(m, grade)
    nx, ny = len(xs), len(ys)

    def node(i, j, k):
        return 1 + i + nx * (j + ny * k)
    used = set()
    elements = []
    for i, j, k in cells:
        ids = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
               node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
        used.update(ids)
        elements.append(ids)
    lines = ["** 3D blade flexure hinge, level m = %d, grade %g (cases/benchmarks/peers/hinge_mesh.py)" % (m, grade),
             "*NODE"]
    for k, z in enumerate(zs):
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                if node(i, j, k) in used:
                    lines.append("%d, %.12g, %.12g, %.12g" % (node(i, j, k), x, y, z))
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=hinge")
    lines += ["%d, %s" % (e + 1, ", ".join(map(str, ids))) for e, ids in enumerate(elements)]
    for name, i in (("clamped", 0), ("turned", nx - 1)):
        ids = sorted(n for n in used if (n - 1) % nx == i)
        lines.append("*NSET, NSET=%s" % name)
        lines += [", ".join(map(str, ids[s:s + 16])) for s in range(0, len(ids), 16)]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) not in (4, 5) or sys.argv[1] != "inp":
        sys.exit("usage: hinge_mesh.py inp M FILE [GRADE]")
    write_inp(int(sys.argv[2]), sys.argv[3], float(sys.argv[4]) if len(sys.argv) == 5 else 1.0)
