#!/usr/bin/env python3
"""Life-curve chart from a fatigue_life --summary-csv file.

Draws the model's three life curves (low / nominal / high parameter sets, equivalent amplitude
against cycles to failure), the curves after lifting to a run-out where they contradicted it
(dashed), every counted cycle of every hot spot at its nominal life, the run-out as a point with an
arrow (a lower bound: the true life lies to the right), and the target life.

usage: /usr/bin/python3 postproc/fatigue_life_chart.py SUMMARY.csv OUT.png [--target 1e6] [--title T]
"""
import argparse
import csv
import math

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_summary(path):
    meta = {"curve": {}, "constrained_curve": {}}
    rows = []
    with open(path) as f:
        data_lines = []
        for line in f:
            if line.startswith("#"):
                fields = [x.strip() for x in line[1:].strip().split(",")]
                key = fields[0]
                if key in ("curve", "constrained_curve"):
                    meta[key][fields[1]] = tuple(float(x) for x in fields[2:6])
                elif key in ("quantity", "model", "critical", "run_out"):
                    meta[key] = fields[1:]
            else:
                data_lines.append(line)
        rows = list(csv.DictReader(data_lines))
    if not meta["curve"]:
        raise SystemExit(f"{path}: no '# curve' lines; expected a fatigue_life --summary-csv file")
    return meta, rows


def curve_points(params, n_min, n_max):
    a_ref, n_ref, k, _ = params
    ns = [n_min * (n_max / n_min) ** (i / 200) for i in range(201)]
    return ns, [a_ref * (n / n_ref) ** (-1.0 / k) for n in ns]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("summary")
    parser.add_argument("out")
    parser.add_argument("--target", type=float, default=1e6)
    parser.add_argument("--title", default=None)
    args = parser.parse_args()
    meta, rows = read_summary(args.summary)

    n_min, n_max = 1e3, 1e12
    colours = {"low": "tab:red", "nominal": "tab:blue", "high": "tab:green"}
    fig, ax = plt.subplots(figsize=(7.5, 5))
    for member, params in meta["curve"].items():
        ns, amps = curve_points(params, n_min, n_max)
        ax.loglog(ns, amps, color=colours[member], label=f"{member}: a_ref {params[0]:.4g}, k {params[2]:g}")
        lifted = meta["constrained_curve"].get(member)
        if lifted and abs(lifted[0] - params[0]) > 1e-12 * params[0]:
            ns, amps = curve_points(lifted, n_min, n_max)
            ax.loglog(ns, amps, color=colours[member], ls="--",
                      label=f"{member} lifted to the run-out: a_ref {lifted[0]:.4g}")

    markers = "osD^v<>"
    names = list(dict.fromkeys(r["hot_spot"] for r in rows))
    for i, name in enumerate(names):
        pts = [(float(r["cycles_nominal"]), float(r["equivalent_amplitude"])) for r in rows
               if r["hot_spot"] == name and float(r["equivalent_amplitude"]) > 0
               and math.isfinite(float(r["cycles_nominal"]))]
        if pts:
            critical = meta.get("critical", [""])[0] == name
            ax.loglog(*zip(*pts), ls="none", marker=markers[i % len(markers)], mfc="none" if not critical else None,
                      color="k", label=f"cycles of '{name}' at nominal life" + (" (critical)" if critical else ""))

    if "run_out" in meta:
        n_s, a_s = float(meta["run_out"][0]), float(meta["run_out"][1])
        if a_s > 0:
            ax.plot([n_s], [a_s], marker="o", color="tab:purple", ls="none",
                    label=f"run-out {n_s:,.0f} (damage-equivalent amplitude of the critical spot)")
            ax.annotate("", xy=(n_s * 8, a_s), xytext=(n_s, a_s),
                        arrowprops=dict(arrowstyle="->", color="tab:purple"))
    ax.axvline(args.target, color="grey", ls=":", label=f"target {args.target:,.0f} cycles")

    quantity = meta.get("quantity", ["strain", ""])
    unit = quantity[1] if len(quantity) > 1 and quantity[1] else ""
    ax.set_xlabel("cycles to failure N")
    ax.set_ylabel(f"equivalent {quantity[0]} amplitude" + (f" [{unit}]" if unit else ""))
    ax.set_xlim(n_min, n_max)
    ax.grid(True, which="both", alpha=0.3)
    ax.set_title(args.title or f"{meta.get('model', ['?'])[0]} (ASSUMED curves, see solver/fatigue/README.md)", fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(args.out, dpi=130)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
