#!/usr/bin/python3
"""Mode shapes of a modal run, drawn in the x-y plane over the undeformed mesh.

    mode_shapes_chart.py RESULTS_DIR [--modes 5] [--scale 0.05] [--out modes.png]

RESULTS_DIR holds fields.h5 and summary.json of an 'Analysis = modal' run. The written modes have
a largest displacement of 1; --scale is the drawn amplitude as a fraction of the model's size.
"""
import argparse
import json
import os

import h5py
import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("results")
    ap.add_argument("--modes", type=int, default=5)
    ap.add_argument("--scale", type=float, default=0.05)
    ap.add_argument("--out", default="modes.png")
    args = ap.parse_args()
    q = json.load(open(os.path.join(args.results, "summary.json")))["quantities"]
    with h5py.File(os.path.join(args.results, "fields.h5")) as f:
        x, cells = f["nodes"][:, :2], f["cells"][:]
        modes = [f["mode_%d" % (m + 1)][:] for m in range(args.modes)]
    size = np.ptp(x, axis=0).max()
    corners = cells[:, :4] if cells.shape[1] in (4, 8) else cells[:, :3]
    if cells.shape[1] in (4, 8):  # deal.II numbers quadrilateral vertices lexicographically
        corners = corners[:, [0, 1, 3, 2]]
    fig, axes = plt.subplots(1, args.modes, figsize=(3.2 * args.modes, 4.2))
    for m, ax in enumerate(np.atleast_1d(axes)):
        y = x + args.scale * size * modes[m][:, :2]
        ax.add_collection(PolyCollection(x[corners], facecolor="none", edgecolor="0.75", lw=0.1))
        ax.add_collection(PolyCollection(y[corners], facecolor="C0", edgecolor="none", alpha=0.6))
        ax.autoscale()
        ax.set_aspect("equal")
        ax.axis("off")
        ax.set_title("mode %d: %.1f Hz" % (m + 1, q["frequency_%d" % (m + 1)]), fontsize=9)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
