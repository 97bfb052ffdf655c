#!/usr/bin/python3
"""Moment-rotation curve of a flexure hinge driven by an end moment (curve.csv of a nonlinear run
with the derived quantities link_angle, link_angle_deg, moment and prbm_moment and the link point
b, as in cases/flexure_hinge_large_rotation.prm) against two pseudo-rigid-body models (Howell,
Compliant Mechanisms, 2001, ch. 5; ../shared/reference/closed-forms.md):

- small-length flexural pivot: K = E I / l, pivot at the flexure centre;
- cantilever PRBM for an end moment: gamma = 0.7346, c_theta = 1.5164, K = 1.5164 E I / l on the
  pseudo-angle Theta = theta0 / c_theta, pivot at (1 - gamma) l from the root.

For a pure end moment both give the same moment for a link rotation theta0 (M = E I theta0 / l,
exact for an inextensible elastica); they differ in where they put the link. The chart therefore
shows the moment departure and the position error of link point b for each model, and marks where
a model departs by more than 5 %.

    postproc/flexure_prbm_chart.py results/flexure_hinge_large_rotation/curve.csv [more.csv ...] --out chart.png
"""
import argparse
import csv
import json
import math
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

GAMMA_MOMENT, C_THETA_MOMENT = 0.7346, 1.5164

ap = argparse.ArgumentParser()
ap.add_argument("curves", nargs="+")
ap.add_argument("--out", default="flexure_prbm.png")
ap.add_argument("--labels", default="")
ap.add_argument("--point-offset", type=float, default=5.0,
                help="link point b sits this far before the link end (x = l + Ll - offset), as in the case file")
args = ap.parse_args()
labels = args.labels.split(",") if args.labels else args.curves


def pivot_prediction(l, s, theta0):
    """Small-length pivot: the flexure end and the link rotate rigidly about (l/2, 0)."""
    r = l / 2 + s
    return l / 2 + r * math.cos(theta0), r * math.sin(theta0)


def cantilever_prediction(l, s, theta0):
    """Cantilever PRBM, end moment: pseudo-link gamma l at Theta, the link leaves the tip at theta0."""
    Theta = theta0 / C_THETA_MOMENT
    tip_x = (1 - GAMMA_MOMENT) * l + GAMMA_MOMENT * l * math.cos(Theta)
    tip_y = GAMMA_MOMENT * l * math.sin(Theta)
    return tip_x + s * math.cos(theta0), tip_y + s * math.sin(theta0)


def first_beyond(angles, departures, limit=5.0):
    beyond = [a for a, d in zip(angles, departures) if abs(d) > limit]
    return "from %.1f deg on" % beyond[0] if beyond else "nowhere up to %.1f deg" % angles[-1]


fig, (ax, ax2) = plt.subplots(2, 1, figsize=(6.5, 7.5), sharex=True)
for path, label in zip(args.curves, labels):
    rows = list(csv.DictReader(open(path)))
    parameters = json.load(open(os.path.join(os.path.dirname(path), "summary.json")))["parameters"]
    l, s = parameters["l"], parameters["Ll"] - args.point_offset
    angle = [float(r["link_angle_deg"]) for r in rows]
    fe = [float(r["moment"]) for r in rows]
    prbm = [float(r["prbm_moment"]) for r in rows]
    moment_departure = [100 * (m / p - 1) for m, p in zip(fe, prbm)]
    position_error = {"pivot": [], "cantilever": []}
    for r in rows:
        theta0 = float(r["link_angle"])
        bx, by = l + s + float(r["displacement_b_x"]), float(r["displacement_b_y"])
        moved = math.hypot(float(r["displacement_b_x"]), float(r["displacement_b_y"]))
        for name, model in (("pivot", pivot_prediction), ("cantilever", cantilever_prediction)):
            px, py = model(l, s, theta0)
            position_error[name].append(100 * math.hypot(px - bx, py - by) / moved)
    line, = ax.plot([0] + angle, [0] + fe, "o-", ms=3, label="FE " + label)
    ax.plot([0] + angle, [0] + prbm, "--", color=line.get_color(),
            label="PRBM: pivot E I / l and cantilever (end moment) " + label)
    ax2.plot(angle, moment_departure, "o-", ms=3, color=line.get_color(), label="moment, both PRBMs " + label)
    ax2.plot(angle, position_error["pivot"], "s:", ms=3, color=line.get_color(),
             label="link position, pivot at l/2 " + label)
    ax2.plot(angle, position_error["cantilever"], "^-.", ms=3, color=line.get_color(),
             label="link position, cantilever PRBM " + label)
    print("%s: moment (both PRBMs) departs by more than 5 %% %s" % (label, first_beyond(angle, moment_departure)))
    for name in ("pivot", "cantilever"):
        print("%s: link position, %s PRBM, departs by more than 5 %% of the link displacement %s "
              "(%.2f %% at %.1f deg)" % (label, name, first_beyond(angle, position_error[name]),
                                          position_error[name][-1], angle[-1]))
ax.set_ylabel("moment per unit width")
ax.legend(fontsize=7)
ax.grid(True, alpha=0.3)
ax2.axhspan(-5, 5, color="green", alpha=0.1, label="within 5 %")
ax2.set_xlabel("link rotation (deg)")
ax2.set_ylabel("FE against PRBM (%)")
ax2.grid(True, alpha=0.3)
ax2.legend(fontsize=7)
fig.tight_layout()
fig.savefig(args.out, dpi=110)
print("chart:", args.out)
