#!/usr/bin/python3
"""Charts of a burmester_synthesis run: the Burmester curves (centre points M, circle points K) with
the precision positions, the spar at each position, the nearest single pivot and the pivots of the
first-ranked mechanism; and that mechanism drawn at the four positions, or, when no four-bar is
defect-free (mechanisms.csv empty), the single pivot carrying the spar.
Run: /usr/bin/python3 cases/morphing_wing/burmester_chart.py cases/morphing_wing/table3"""
import cmath
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

folder = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "table3")
curves = list(csv.DictReader(open(os.path.join(folder, "burmester_curves.csv"))))
positions = list(csv.DictReader(open(os.path.join(folder, "positions.csv"))))
mechanisms = list(csv.DictReader(open(os.path.join(folder, "mechanisms.csv"))))
spar = 0.08  # drawn spar height below its top point (chords)

R = [complex(float(p["x"]), float(p["y"])) for p in positions]
angle = [math.radians(float(p["angle_deg"])) for p in positions]

fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 6))
for ax in (ax1, ax2):
    for j, (r, a) in enumerate(zip(R, angle)):
        bottom = r - spar * cmath.exp(1j * a)
        ax.plot([r.real, bottom.real], [r.imag, bottom.imag], "k-", lw=3, alpha=0.3 + 0.2 * j)
        ax.plot(r.real, r.imag, "ko", ms=4)
        ax.annotate(str(j + 1), (r.real, r.imag), textcoords="offset points", xytext=(4, 4))
    ax.set_aspect("equal")
    ax.grid(alpha=0.3)
    ax.set_xlabel("x (chords)")
    ax.set_ylabel("y (chords)")

def inside(z):
    return -1.0 < z.real < 2.5 and -2.5 < z.imag < 1.0

M = [complex(float(c["Mx"]), float(c["My"])) for c in curves]
K = [complex(float(c["Kx"]), float(c["Ky"])) for c in curves]
ax1.plot([m.real for m in M if inside(m)], [m.imag for m in M if inside(m)], ".", ms=2, label="centre points M")
ax1.plot([k.real for k in K if inside(k)], [k.imag for k in K if inside(k)], ".", ms=2, label="circle points K")
# Nearest pure rotation (least squares over the centre), as the executable prints it.
e = [cmath.exp(1j * (a - angle[0])) for a in angle]
c = sum((1 - ej).conjugate() * (r - ej * R[0]) for r, ej in zip(R, e)) / sum(abs(1 - ej) ** 2 for ej in e)
ax1.plot(c.real, c.imag, "r*", ms=14, label="nearest single pivot")
# A unit-chord section outline for scale: leading edge at the origin, trailing edge at x = 1.
ax1.plot([0, 1], [0, 0], "c-", lw=1, label="chord 1 (position 1)")
if mechanisms:
    m = mechanisms[0]
    A, D = complex(float(m["Ax"]), float(m["Ay"])), complex(float(m["Dx"]), float(m["Dy"]))
    ax1.plot([A.real, D.real], [A.imag, D.imag], "gs", ms=8, label="ranked #1: ground pivots")
ax1.set_title("Burmester curves, paper Table 3 positions")
ax1.legend(loc="lower left", fontsize=8)
ax1.set_xlim(-0.2, 2.0)
ax1.set_ylim(-2.2, 0.6)

if mechanisms:
    m = mechanisms[0]
    A, B1 = complex(float(m["Ax"]), float(m["Ay"])), complex(float(m["Bx"]), float(m["By"]))
    D, C1 = complex(float(m["Dx"]), float(m["Dy"])), complex(float(m["Cx"]), float(m["Cy"]))
    for j, (r, a) in enumerate(zip(R, angle)):
        # The coupler is rigid: every point of it moves with the spar from position 1.
        rot = cmath.exp(1j * (a - angle[0]))
        B, C = r + rot * (B1 - R[0]), r + rot * (C1 - R[0])
        style = dict(alpha=0.35 + 0.2 * j, lw=1.5)
        ax2.plot([A.real, B.real], [A.imag, B.imag], "b-", **style)
        ax2.plot([D.real, C.real], [D.imag, C.imag], "g-", **style)
        ax2.fill([B.real, C.real, r.real], [B.imag, C.imag, r.imag], color="orange", alpha=0.15)
        ax2.plot([B.real, C.real, r.real, B.real], [B.imag, C.imag, r.imag, B.imag], "-", color="orange", **style)
    ax2.plot([A.real, D.real], [A.imag, D.imag], "ks", ms=8)
    ax2.set_title("ranked #1 (%s, %s; transmission %s-%s deg over the motion)"
                  % (m["grashof"], "defect: " + m["defect"], m["mu_min_motion_deg"], m["mu_max_motion_deg"]),
                  fontsize=9)
else:
    # No defect-free four-bar: the answer is the single revolute joint at the pole.
    for j, (r, a) in enumerate(zip(R, angle)):
        rot = cmath.exp(1j * (a - angle[0]))
        rigid = c + rot * (R[0] - c)
        ax2.plot([c.real, rigid.real], [c.imag, rigid.imag], "r-", alpha=0.35 + 0.2 * j, lw=1.5)
        ax2.plot(rigid.real, rigid.imag, "rx", ms=6)
    ax2.plot(c.real, c.imag, "r*", ms=14)
    ax2.set_title("no defect-free four-bar within the link bounds: the single pivot (arm to the spar,\n"
                  "x where the rigid arm puts the spar point)", fontsize=9)
fig.tight_layout()
out = os.path.join(folder, "..", "burmester.png")
fig.savefig(out, dpi=110)
print("wrote", os.path.normpath(out))
