#!/usr/bin/python3
"""Charts from study tables: postproc/chart.py study.csv x:y [out_folder]."""
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def plot_study(table, spec, out_dir):
    x_name, y_name = spec.split(":", 1)
    with open(table) as f:
        # failed points of a study have a status other than ok and no values
        rows = [r for r in csv.DictReader(f) if r.get("status", "ok") == "ok"]
    x = [float(r[x_name]) for r in rows]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(x, [float(r[y_name]) for r in rows], "o-", label="FE: " + y_name)
    for column in rows[0]:
        if column.startswith("ref:" + y_name + "~"):
            ax.plot(x, [float(r[column]) for r in rows], "--", label=column.split("~", 1)[1])
    ax.set_xlabel(x_name)
    ax.set_ylabel(y_name)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    path = os.path.join(out_dir, "%s_vs_%s.png" % (y_name, x_name))
    fig.savefig(path, dpi=120)
    return path


if __name__ == "__main__":
    print(plot_study(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) > 3 else "."))
