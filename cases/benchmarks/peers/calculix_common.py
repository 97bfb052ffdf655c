"""What the CalculiX peer scripts share: a structured mesh of 20-node hexahedra on tensor grid
lines (so that CalculiX solves the same cells as ours and FEniCSx), its *NODE and *ELEMENT cards,
and one timed ccx run with 2 threads (OMP_NUM_THREADS, CCX_NPROC_EQUATION_SOLVER) that reports the
wall time of the whole process and its peak memory."""
import os
import re
import subprocess
import time

# Local corner/mid-side offsets in CalculiX's C3D20 order (corners 1-8, then edges 9-20), on the
# grid of corner and mid-side points (index 2i on grid line i, 2i + 1 half-way to the next).
C3D20_ORDER = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
               (1, 0, 0), (2, 1, 0), (1, 2, 0), (0, 1, 0), (1, 0, 2), (2, 1, 2), (1, 2, 2), (0, 1, 2),
               (0, 0, 1), (2, 0, 1), (2, 2, 1), (0, 2, 1)]


def uniform(lo, hi, cells):
    """Grid line coordinates of `cells` equal cells on [lo, hi]."""
    return [lo + (hi - lo) * i / cells for i in range(cells + 1)]


def graded(lo, hi, cells, grade, ends):
    """Grid lines of meshes/graded_layers.geo: cell lengths in geometric progression away from the
    graded end(s), the longest `grade` times the shortest; ends 0 both, 1 at lo, 2 at hi."""
    if grade == 1:
        return uniform(lo, hi, cells)
    steps = (cells - 1) // 2 if ends == 0 else cells - 1
    if steps < 1:
        raise ValueError("graded: %d cells cannot grade %s" % (cells, "both ends" if ends == 0 else "one end"))
    ratio = grade ** (1.0 / steps) if steps > 0 else 1.0
    k = [i if ends == 1 else cells - 1 - i if ends == 2 else min(i, cells - 1 - i) for i in range(cells)]
    lengths = [ratio ** j for j in k]
    total, lines = sum(lengths), [lo]
    for length in lengths:
        lines.append(lines[-1] + (hi - lo) * length / total)
    lines[-1] = hi
    return lines


class Hex20Grid:
    """The 20-node hexahedra of the cells (a, b, c) of the grid lines xyz (all cells if None).
    Node ids number the fine (2nx+1) x (2ny+1) x (2nz+1) grid; `used` maps the ids of the nodes the
    elements use to their fine-grid indices (face and cell centres are not nodes of C3D20)."""

    def __init__(self, xyz, cells=None):
        self.xyz = xyz
        self.nx, self.ny, self.nz = (len(g) - 1 for g in xyz)
        if cells is None:
            cells = [(a, b, c) for c in range(self.nz) for b in range(self.ny) for a in range(self.nx)]
        self.elements, self.used = [], {}
        for a, b, c in cells:
            ids = []
            for di, dj, dk in C3D20_ORDER:
                ijk = (2 * a + di, 2 * b + dj, 2 * c + dk)
                self.used[self.node_id(*ijk)] = ijk
                ids.append(self.node_id(*ijk))
            self.elements.append(ids)

    def node_id(self, i, j, k):
        return 1 + i + (2 * self.nx + 1) * (j + (2 * self.ny + 1) * k)

    def coordinates(self, i, j, k):
        """Even indices on the grid lines, odd ones half-way between."""
        return tuple(g[c // 2] if c % 2 == 0 else 0.5 * (g[c // 2] + g[c // 2 + 1])
                     for g, c in zip(self.xyz, (i, j, k)))

    def nodes_where(self, axis, index):
        """Ids of the used nodes on the fine-grid plane `index` normal to `axis` (0, 1, 2)."""
        return sorted(nid for nid, ijk in self.used.items() if ijk[axis] == index)

    def deck(self, element_type="C3D20R", elset="EALL"):
        """The *NODE and *ELEMENT cards (an element's 20 ids over two lines, 15 + 5)."""
        lines = ["*NODE"] + ["%d, %.12g, %.12g, %.12g" % ((nid,) + self.coordinates(*ijk))
                             for nid, ijk in sorted(self.used.items())]
        lines.append("*ELEMENT, TYPE=%s, ELSET=%s" % (element_type, elset))
        for e, ids in enumerate(self.elements):
            lines.append("%d, %s," % (e + 1, ", ".join(map(str, ids[:15]))))
            lines.append(", ".join(map(str, ids[15:])))
        return lines


def run_ccx(work, lines, job="job"):
    """Writes WORK/JOB.inp, runs ccx there with 2 threads; returns (wall s, peak MB). A failed run
    exits with the tail of ccx's output, so that the benchmark's table shows why it was skipped."""
    with open(os.path.join(work, job + ".inp"), "w") as f:
        f.write("\n".join(lines) + "\n")
    env = dict(os.environ, OMP_NUM_THREADS="2", CCX_NPROC_EQUATION_SOLVER="2")
    start = time.perf_counter()
    proc = subprocess.run(["/usr/bin/time", "-f", "MAXRSS %M", "ccx", "-i", job], cwd=work,
                          capture_output=True, text=True, env=env)
    wall = time.perf_counter() - start
    if proc.returncode != 0 or "*ERROR" in proc.stdout:
        raise SystemExit("ccx failed: " + proc.stdout[-500:] + proc.stderr[-500:])
    return wall, float(re.findall(r"MAXRSS (\d+)", proc.stderr)[-1]) / 1024.0
