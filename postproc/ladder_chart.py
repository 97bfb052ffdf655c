#!/usr/bin/python3
"""Accuracy against time from a model-ladder run (its ladder.csv): for each target quantity the
estimated relative error of every rung (and the true error where a reference is given) against the
cumulative wall time, log-log, the chosen (last) rung marked and the target drawn.
Run: /usr/bin/python3 postproc/ladder_chart.py results/<case>/ladder.csv --target 0.5 [--reference name=value]"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

parser = argparse.ArgumentParser(description=__doc__)
parser.add_argument("ladder_csv")
parser.add_argument("--target", type=float, required=True, help="percent")
parser.add_argument("--reference", action="append", default=[], help="quantity=value (true error)")
parser.add_argument("--out", default=None)
args = parser.parse_args()
rows = list(csv.DictReader(open(args.ladder_csv)))
names = [k for k in rows[0] if k not in ("rung", "model", "degree", "refinements", "adaptive_cycles", "dofs", "seconds",
                                          "cumulative_seconds") and not k.startswith("estimate_")
             and not k.startswith("stop_estimate_")]
references = dict((kv.split("=")[0], float(kv.split("=")[1])) for kv in args.reference)
fig, ax = plt.subplots(figsize=(7, 5))
for name in names:
    t = [float(r["cumulative_seconds"]) for r in rows if r["estimate_" + name]]
    e = [100 * float(r["estimate_" + name]) for r in rows if r["estimate_" + name]]
    ax.loglog(t, e, "o-", label="%s, estimate (linear, degree %s)" % (name, rows[0]["degree"]))
    if name in references:
        ref = references[name]
        tt = [float(r["cumulative_seconds"]) for r in rows]
        ee = [100 * abs(float(r[name]) - ref) / abs(ref) for r in rows]
        ax.loglog(tt, ee, "s--", label="%s, true error" % name)
    if t:
        ax.loglog(t[-1], e[-1], "k*", ms=14)
ax.axhline(args.target, color="r", lw=1, label="target %.2g %%" % args.target)
ax.set_xlabel("cumulative wall time of the ladder (s)")
ax.set_ylabel("relative error (%)")
ax.grid(True, which="both", alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
out = args.out or os.path.join(os.path.dirname(args.ladder_csv), "ladder.png")
fig.savefig(out, dpi=110)
print("wrote", out)
