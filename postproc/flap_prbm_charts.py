#!/usr/bin/python3
"""Charts of a flap_prbm run (compliant flap four-bar, seed paper 000).

usage: flap_prbm_charts.py OUTPUT_DIR [--flexure-length-mm L]

Reads flap_kinematics.csv, flap_torque_cycle.csv and flap_ratio_study.csv written by flap_prbm
into OUTPUT_DIR and writes there:
  flap_kinematics.png    coupler/rocker angle, velocity coefficient and transmission angle over
                         two crank turns (the change point swaps the branch each turn)
  flap_torque_cycle.png  crank torque and power over one cycle, rigid and compliant
  flap_torque_ratio.png  peak compliant/rigid torque ratio against l_k for several E, with the
                         paper's "about 3"
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER_RATIO = 3.0


def read_csv(path):
    """Columns of a CSV file as lists (floats where possible)."""
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    if not rows:
        sys.exit(f"flap_prbm_charts: {path} has no data rows")
    columns = {}
    for key in rows[0]:
        values = [row[key] for row in rows]
        try:
            columns[key] = [float(v) for v in values]
        except ValueError:
            columns[key] = values
    return columns


def kinematics_chart(directory):
    k = read_csv(os.path.join(directory, "flap_kinematics.csv"))
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    crank = k["crank_deg"]
    for branch, colour in (("minus", "tab:blue"), ("plus", "tab:red")):
        picked = [i for i, b in enumerate(k["branch"]) if b == branch]
        label = f"root '{branch}' of Eq. E13"
        axes[0].plot([crank[i] for i in picked], [k["rocker_deg"][i] for i in picked], ".",
                     ms=1.5, color=colour, label="rocker th4, " + label)
        axes[0].plot([crank[i] for i in picked], [k["coupler_deg"][i] for i in picked], ".",
                     ms=1.5, color=colour, alpha=0.4)
    axes[0].set_ylabel("angle [deg]")
    axes[0].set_title("Flap four-bar (60/10/65/15 mm, change point): two crank turns, "
                      "branch-tracked\n(faint: coupler th3)")
    axes[0].legend(loc="best", fontsize=8, markerscale=6)
    axes[1].plot(crank, k["dth4_dth2"], label="dth4/dth2")
    axes[1].plot(crank, k["dth3_dth2"], label="dth3/dth2")
    axes[1].set_ylabel("velocity coefficient [-]")
    axes[1].legend(loc="best", fontsize=8)
    axes[2].plot(crank, k["transmission_deg"])
    axes[2].axhline(40, color="grey", ls=":")
    axes[2].axhline(140, color="grey", ls=":")
    axes[2].set_ylabel("transmission angle [deg]")
    axes[2].set_xlabel("crank angle th2 [deg]")
    for ax in axes:
        ax.grid(alpha=0.3)
        for fold in (360.0, 720.0):
            ax.axvline(fold, color="k", lw=0.5, ls="--")
    fig.tight_layout()
    path = os.path.join(directory, "flap_kinematics.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def torque_chart(directory):
    c = read_csv(os.path.join(directory, "flap_torque_cycle.csv"))
    t = c["time_s"]
    fig, axes = plt.subplots(3, 1, figsize=(8, 9), sharex=True)
    axes[0].plot(t, c["crank_deg"], label="crank th2")
    axes[0].plot(t, c["rocker_deg"], label="rocker th4 (flap)")
    axes[0].set_ylabel("angle [deg]")
    axes[0].legend(fontsize=8)
    axes[0].set_title("One motor turn at constant speed: torque on the crank AB")
    axes[1].plot(t, c["T_compliant_Nm"], label="compliant: inertia + gravity + PRBM springs")
    axes[1].plot(t, c["T_spring_Nm"], "--", label="springs alone (Eq. 12)")
    axes[1].set_ylabel("torque [N m]")
    axes[1].legend(fontsize=8)
    micro = 1e6
    axes[2].plot(t, [v * micro for v in c["T_rigid_Nm"]], label="rigid: inertia + gravity")
    axes[2].plot(t, [v * micro for v in c["T_inertia_Nm"]], label="rigid: inertia only")
    axes[2].set_ylabel("torque [uN m]")
    axes[2].set_xlabel("time [s]")
    axes[2].legend(fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.tight_layout()
    path = os.path.join(directory, "flap_torque_cycle.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def ratio_chart(directory, flexure_length_mm):
    r = read_csv(os.path.join(directory, "flap_ratio_study.csv"))
    fig, ax = plt.subplots(figsize=(8, 5.5))
    for modulus in sorted(set(r["youngs_modulus_mpa"])):
        picked = [i for i, e in enumerate(r["youngs_modulus_mpa"]) if e == modulus]
        picked.sort(key=lambda i: r["flexure_length_mm"][i])
        ax.loglog([r["flexure_length_mm"][i] for i in picked],
                  [r["peak_ratio_gravity"][i] for i in picked], "o-",
                  label=f"E = {modulus:g} MPa")
    ax.axhline(PAPER_RATIO, color="k", ls="--", label='paper: "about 3 times"')
    if flexure_length_mm:
        ax.axvline(flexure_length_mm, color="grey", ls=":", label=f"default l_k = {flexure_length_mm:g} mm")
    ax.set_xlabel("flexure length l_k [mm]")
    ax.set_ylabel("peak compliant / rigid crank torque [-]")
    ax.set_title("PRBM torque ratio over one cycle (gravity included)\n"
                 "K = E b h^3 / (12 l_k), b = 1.5 mm, h = 3 mm")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(directory, "flap_torque_ratio.png")
    fig.savefig(path, dpi=130)
    plt.close(fig)
    return path


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("directory", help="output directory of flap_prbm")
    parser.add_argument("--flexure-length-mm", type=float, default=1.0,
                        help="l_k of the run, marked on the ratio chart")
    args = parser.parse_args()
    if not os.path.isdir(args.directory):
        sys.exit(f"flap_prbm_charts: no such directory {args.directory}")
    for path in (kinematics_chart(args.directory), torque_chart(args.directory),
                 ratio_chart(args.directory, args.flexure_length_mm)):
        print("wrote", path)


if __name__ == "__main__":
    main()
