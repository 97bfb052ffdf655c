#!/usr/bin/python3
"""Chart of the Jansen leg kinematics over a crank turn.

Reads the CSV written by `jansen_kinematics --out foot.csv` and draws, in one PNG:
  1. the foot path of H with the leg drawn at its lowest (ground-contact) pose and the
     seed paper's pose theta2 = 302.8 deg marked;
  2. the velocity of H (components and magnitude) against the crank angle;
  3. the acceleration of H against the crank angle.
The seed paper's printed V_H and a_H (Kartal & Kavlak, eqs. 9-11 and 16-18, omega2 = 10 rad/s)
are marked at theta2 = 302.8 deg when --paper is given (default); they only apply at 10 rad/s.

Usage: /usr/bin/python3 postproc/jansen_chart.py foot.csv [--out jansen_chart.png] [--no-paper]
"""
import argparse
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER_THETA2 = 302.8  # deg
PAPER_V_H = (844.72, -75.7, 848.11)  # mm/s: x, y, magnitude
PAPER_A_H = (5081.45, -75.7, 5081.47)  # mm/s^2: x, y, magnitude (y is a misprint, see solver/mechanisms/jansen/README.md)

# Links drawn between joints; the ternary links CDE and FGH are filled triangles.
BINARY_LINKS = [("A", "B"), ("B", "C"), ("B", "G"), ("E", "G"), ("D", "F")]
TERNARY_LINKS = [("C", "D", "E"), ("F", "G", "H")]


def read_rows(path):
    with open(path, newline="") as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    if not rows:
        sys.exit(f"jansen_chart.py: {path} has no data rows")
    for column in ("theta2_deg", "x_H", "y_H", "vx_H", "ax_H", "x_A", "y_G"):
        if column not in rows[0]:
            sys.exit(f"jansen_chart.py: {path} lacks column '{column}': not a jansen_kinematics CSV")
    return rows


def draw_leg(ax, row, colour, label):
    point = {j: (row[f"x_{j}"], row[f"y_{j}"]) for j in "ABCDEFGH"}
    for tri in TERNARY_LINKS:
        xs = [point[j][0] for j in tri]
        ys = [point[j][1] for j in tri]
        ax.fill(xs, ys, color=colour, alpha=0.25, lw=0)
        ax.plot(xs + xs[:1], ys + ys[:1], color=colour, lw=1.5)
    for a, b in BINARY_LINKS:
        ax.plot([point[a][0], point[b][0]], [point[a][1], point[b][1]], color=colour, lw=1.5)
    ax.plot([p[0] for p in point.values()], [p[1] for p in point.values()], "o", color=colour,
            ms=3, label=label)
    for j, (x, y) in point.items():
        ax.annotate(j, (x, y), textcoords="offset points", xytext=(4, 4), fontsize=7, color=colour)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("csv", help="CSV from jansen_kinematics --out")
    parser.add_argument("--out", default="jansen_chart.png", help="PNG to write")
    parser.add_argument("--no-paper", action="store_true", help="do not mark the paper's numbers")
    args = parser.parse_args()

    rows = read_rows(args.csv)
    theta = [r["theta2_deg"] for r in rows]
    lowest = min(rows, key=lambda r: r["y_H"])
    paper_row = min(rows, key=lambda r: abs(((r["theta2_deg"] - PAPER_THETA2 + 180.) % 360.) - 180.))

    fig, axes = plt.subplots(1, 3, figsize=(17, 5.6))

    ax = axes[0]
    ax.plot([r["x_H"] for r in rows], [r["y_H"] for r in rows], "k-", lw=1.2, label="foot path H")
    draw_leg(ax, lowest, "tab:blue", f"lowest foot, theta2 = {lowest['theta2_deg']:.0f} deg (sample)")
    draw_leg(ax, paper_row, "tab:orange", f"paper's pose, theta2 = {paper_row['theta2_deg']:.0f} deg (sample)")
    ax.axhline(lowest["y_H"], color="grey", lw=0.8, ls="--", label="ground (lowest H)")
    bottom, top = ax.get_ylim()
    ax.set_ylim(bottom, top + 0.3 * (top - bottom))  # room for the legend above the leg
    ax.set_aspect("equal")
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("y (mm)")
    ax.set_title("Jansen leg: foot path, E at the origin")
    ax.legend(fontsize=7, loc="upper left")

    for ax, prefix, name, unit, paper in ((axes[1], "v", "velocity", "mm/s", PAPER_V_H),
                                          (axes[2], "a", "acceleration", "mm/s$^2$", PAPER_A_H)):
        ax.plot(theta, [r[f"{prefix}x_H"] for r in rows], label=f"{prefix}_Hx")
        ax.plot(theta, [r[f"{prefix}y_H"] for r in rows], label=f"{prefix}_Hy")
        ax.plot(theta, [r[f"{prefix}_H"] for r in rows], "k-", lw=1.5, label=f"|{prefix}_H|")
        if not args.no_paper:
            ax.plot([PAPER_THETA2] * 3, paper, "rx", ms=8, mew=2,
                    label="paper, theta2 = 302.8 deg (10 rad/s)")
        ax.axvline(lowest["theta2_deg"], color="grey", lw=0.8, ls="--")
        ax.axhline(0., color="grey", lw=0.5)
        ax.set_xlim(0., 360.)
        ax.set_xticks(range(0, 361, 60))
        ax.set_xlabel("crank angle theta2 (deg)")
        ax.set_ylabel(f"foot {name} ({unit})")
        ax.set_title(f"{name.capitalize()} of the foot H (dashed: lowest foot)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)

    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
