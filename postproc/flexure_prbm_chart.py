#!/usr/bin/python3
"""Moment-rotation curve of a flexure hinge (curve.csv of a nonlinear run with the derived
quantities link_angle_deg, moment and prbm_moment, as in cases/flexure_hinge_large_rotation.prm)
against the PRBM K = E I / l, marking where the PRBM departs by more than 5 %.

    postproc/flexure_prbm_chart.py results/flexure_hinge_large_rotation/curve.csv [more.csv ...] --out chart.png
"""
import argparse
import csv

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

ap = argparse.ArgumentParser()
ap.add_argument("curves", nargs="+")
ap.add_argument("--out", default="flexure_prbm.png")
ap.add_argument("--labels", default="")
args = ap.parse_args()
labels = args.labels.split(",") if args.labels else args.curves

fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.5, 7), sharex=True)
for path, label in zip(args.curves, labels):
    rows = list(csv.DictReader(open(path)))
    angle = [0.0] + [float(r["link_angle_deg"]) for r in rows]
    fe = [0.0] + [float(r["moment"]) for r in rows]
    prbm = [0.0] + [float(r["prbm_moment"]) for r in rows]
    departure = [100 * (float(r["moment"]) / float(r["prbm_moment"]) - 1) for r in rows]
    line, = ax.plot(angle, fe, "o-", ms=3, label="FE " + label)
    ax.plot(angle, prbm, "--", color=line.get_color(), label="PRBM E I / l " + label)
    ax2.plot(angle[1:], departure, "o-", ms=3, color=line.get_color(), label=label)
    beyond = [a for a, d in zip(angle[1:], departure) if abs(d) > 5]
    print("%s: PRBM departs by more than 5 %% %s" % (
        label, "from %.1f deg on" % beyond[0] if beyond else "nowhere up to %.1f deg" % angle[-1]))
ax.set_ylabel("moment per unit width")
ax.legend(fontsize=8)
ax.grid(True, alpha=0.3)
ax2.axhspan(-5, 5, color="green", alpha=0.1, label="within 5 %")
ax2.set_xlabel("link rotation (deg)")
ax2.set_ylabel("FE / PRBM - 1 (%)")
ax2.grid(True, alpha=0.3)
ax2.legend(fontsize=8)
fig.tight_layout()
fig.savefig(args.out, dpi=110)
print("chart:", args.out)
