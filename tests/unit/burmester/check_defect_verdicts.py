#!/usr/bin/python3
"""Independent check of burmester_synthesis's defect verdicts (issue 26), sharing no code with it.

For every candidate in OUT/candidates.csv: the coupler carries B and C rigidly from position 1 to each
position; the assembly there is the side of the line B -> D on which C lies; the input angle is
arg(B - A). The input must meet the positions in order turning one way (either way round), and along
that sweep, sampled every 0.01 degrees (plus the positions themselves), the diagonal |B - D| must stay
strictly between |BC - DC| and BC + DC (no toggle, no place where the chain cannot close). A candidate
is defect-free by this check iff it is in order, on one assembly at all four positions, and without a
toggle on the way. Every candidate reported 'none' must pass; every candidate this check calls clean
must be reported 'none', unless the reported distance to a toggle is below the sampling step.
It also recomputes the transmission angle at the positions and the paper's filter (Grashof, link
bounds and transmission angle limits read from the case file) for every candidate.
Usage: check_defect_verdicts.py CASE OUT [CANDIDATES CLEAN]  (the case file, the folder
burmester_synthesis wrote; optionally the number of candidates and of defect-free ones by this check
that the README states, which must then match exactly)."""
import csv
import math
import os
import sys

import numpy as np

if len(sys.argv) not in (3, 5):
    sys.exit("usage: check_defect_verdicts.py CASE OUT [CANDIDATES CLEAN]")
case, folder = sys.argv[1], sys.argv[2]
pos = list(csv.DictReader(open(os.path.join(folder, "positions.csv"))))
R = np.array([complex(float(p["x"]), float(p["y"])) for p in pos])
turn = np.exp(1j * np.radians([float(p["angle_deg"]) - float(pos[0]["angle_deg"]) for p in pos]))
rows = list(csv.DictReader(open(os.path.join(folder, "candidates.csv"))))
if not rows:
    sys.exit("FAIL: no candidates in " + folder)
col = lambda k: np.array([float(r[k]) for r in rows])
A, B1 = col("Ax") + 1j * col("Ay"), col("Bx") + 1j * col("By")
D, C1 = col("Dx") + 1j * col("Dy"), col("Cx") + 1j * col("Cy")
reported_clean = np.array([r["defect"] == "none" for r in rows])
margin_input = np.radians(col("toggle_margin_input_deg"))

B = R[None, :] + (B1 - R[0])[:, None] * turn[None, :]  # (candidate, position)
C = R[None, :] + (C1 - R[0])[:, None] * turn[None, :]
cross = ((D[:, None] - B) * np.conj(C - B)).imag  # sign: C left (+) / right (-) of B -> D
side = np.sign(-cross)
one_assembly = np.all(side == side[:, :1], axis=1) & np.all(side != 0, axis=1)

theta = np.angle(B - A[:, None])
crank, coupler, rocker = np.abs(B1 - A), np.abs(C1 - B1), np.abs(C1 - D)
lo, hi = np.abs(coupler - rocker), coupler + rocker


def travel(sense):
    return np.mod(sense[:, None] * (theta - theta[:, :1]), 2 * math.pi)


forward, backward = travel(np.ones(len(rows))), travel(-np.ones(len(rows)))
in_order_f = (forward[:, 1] < forward[:, 2]) & (forward[:, 2] < forward[:, 3])
in_order_b = (backward[:, 1] < backward[:, 2]) & (backward[:, 2] < backward[:, 3])
in_order = in_order_f | in_order_b
sense = np.where(in_order_b & ~in_order_f, -1.0, 1.0)
sweep = np.where(sense > 0, forward[:, 3], backward[:, 3])

step = math.radians(0.01)
no_toggle = np.ones(len(rows), dtype=bool)
for k in np.nonzero(in_order & one_assembly)[0]:
    t = np.append(np.arange(0.0, sweep[k], step), sweep[k])
    s = np.abs(A[k] + crank[k] * np.exp(1j * (theta[k, 0] + sense[k] * t)) - D[k])
    no_toggle[k] = bool(np.all(s > lo[k]) and np.all(s < hi[k]))
clean = in_order & one_assembly & no_toggle

# The transmission angle (angle BCD) at the positions, and the paper's filter built on it: Grashof
# (shortest + longest < the other two), links within the case's bounds, 40-140 degrees at the positions.
ground = np.abs(D - A)
mu = np.degrees(np.arccos(np.clip((coupler[:, None] ** 2 + rocker[:, None] ** 2 - np.abs(B - D[:, None]) ** 2)
                                  / (2 * coupler * rocker)[:, None], -1, 1)))
mu_error = max(np.max(np.abs(mu.min(axis=1) - col("mu_min_positions_deg")) / np.maximum(1, mu.min(axis=1))),
               np.max(np.abs(mu.max(axis=1) - col("mu_max_positions_deg")) / np.maximum(1, mu.max(axis=1))))
links = np.sort(np.stack([ground, crank, coupler, rocker]), axis=0)
grashof = links[0] + links[3] < links[1] + links[2]
bounds = {"transmission angle min": 40, "transmission angle max": 140, "minimum link length": 0.02,
          "maximum link length": 1.0}  # the executable's documented defaults, overridden by the case file
for line in open(case):
    key, _, value = line.split("#")[0].partition("=")
    if key.strip() in bounds:
        bounds[key.strip()] = float(value)
paper = (grashof & (links[3] <= bounds["maximum link length"]) & (links[0] >= bounds["minimum link length"])
         & (mu.min(axis=1) >= bounds["transmission angle min"]) & (mu.max(axis=1) <= bounds["transmission angle max"]))
reported_paper = np.array([r["paper_criteria"] == "1" for r in rows])
print("transmission angle at the positions: largest difference %.1e deg (relative above 1 deg);"
      " paper's filter: %d reported, %d by this check" % (mu_error, reported_paper.sum(), paper.sum()))
if mu_error > 2e-5 or np.any(paper != reported_paper):
    sys.exit("FAIL: transmission angles or the paper's filter differ")

false_clean = np.nonzero(reported_clean & ~clean)[0]
missed = np.nonzero(~reported_clean & clean & (margin_input > step))[0]
print("%d candidates: %d reported defect-free, %d defect-free by the independent check"
      % (len(rows), reported_clean.sum(), clean.sum()))
for k in false_clean[:5]:
    print("  reported 'none' but: in order %s, one assembly %s (signs %s), no toggle %s"
          % (in_order[k], one_assembly[k], side[k], no_toggle[k]))
for k in missed[:5]:
    print("  reported '%s' but clean by the check" % rows[k]["defect"])
if len(false_clean) or len(missed):
    sys.exit("FAIL: %d reported defect-free wrongly, %d clean ones reported defective"
             % (len(false_clean), len(missed)))
if len(sys.argv) == 5 and (len(rows), int(clean.sum())) != (int(sys.argv[3]), int(sys.argv[4])):
    sys.exit("FAIL: %d candidates, %d defect-free by this check; the README states %s and %s"
             % (len(rows), clean.sum(), sys.argv[3], sys.argv[4]))
print("PASS")
