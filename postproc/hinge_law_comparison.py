#!/usr/bin/python3
"""Does the hyperelastic law matter for a printed-TPU flexure at large rotation? Runs
cases/flexure_hinge_large_rotation.prm (plane strain, mixed u-p, end moment by a follower pressure)
with the fitted TPU entry (library 'semiflex_fit') twice: neo-Hookean from the entry's E and nu, and
the Ogden law fitted to the same data (postproc/material_data/cheetah_fit/fit.json), whose
small-strain shear modulus is the entry's (E = 2 G (1 + nu)). Both start from the same stiffness,
so what differs is the law's nonlinearity alone. The drive is scaled by E / 89.5 MPa to reach the
case's ~46 degrees. Prints the moment-rotation and peak-strain differences; --out writes a chart.

    /usr/bin/python3 postproc/hinge_law_comparison.py [--law "Ogden 2"] [--np 2] [--out hinge_laws.png]
"""
import argparse
import json
import os
import sys

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
from study import run_case_with_curve  # noqa: E402

root = os.path.join(here, "..")
ap = argparse.ArgumentParser()
ap.add_argument("--law", default="Ogden 2", help="the fitted law (a name in fit.json) against neo-Hookean")
ap.add_argument("--np", type=int, default=2)
ap.add_argument("--out", default="")
args = ap.parse_args()

fit = json.load(open(os.path.join(here, "material_data", "cheetah_fit", "fit.json")))
law = next(r for r in fit["laws"] if r["name"] == args.law)
E = law["E"]  # MPa, = the library entry's
case = os.path.join(root, "cases", "flexure_hinge_large_rotation.prm")
common = ["Material/Materials=*: semiflex_fit", "Quantities/Region maxima=body",
          "Finite strain/Follower pressure=drive: %.10g*y" % (0.0095 * E / 89.5)]
constants = ", ".join("%s=%.17g" % kv for kv in law["constants"].items())
runs = {}
for name, sets in (("neo-Hookean", ["Finite strain/Law=neo-Hookean"]),
                   (args.law, ["Finite strain/Law=" + law["law"], "Finite strain/Law constants=" + constants])):
    summary, curve = run_case_with_curve(case, common + sets, np=args.np)
    runs[name] = {k: np.array([float(row[k]) for row in curve])
                  for k in ("load_factor", "link_angle_deg", "moment", "max_principal_strain_in_body")}
    r = runs[name]
    print("%-12s %d steps: end %.3f deg, moment %.5g N mm/mm, peak principal strain %.5f"
          % (name, len(curve), r["link_angle_deg"][-1], r["moment"][-1], r["max_principal_strain_in_body"][-1]))

a, b = runs["neo-Hookean"], runs[args.law]
# the same load factor is the same applied moment: compare the rotation it gives and the strain
theta_b = np.interp(a["load_factor"], b["load_factor"], b["link_angle_deg"])
strain_b = np.interp(a["load_factor"], b["load_factor"], b["max_principal_strain_in_body"])
# the same rotation: the moment it takes and the strain there
moment_b = np.interp(a["link_angle_deg"], b["link_angle_deg"], b["moment"])
strain_b_at_theta = np.interp(a["link_angle_deg"], b["link_angle_deg"], b["max_principal_strain_in_body"])
ok = a["link_angle_deg"] <= b["link_angle_deg"].max()
print("at equal moment:   rotation %s / neo-Hookean - 1: %+.2f %% (end), max |.| %.2f %%"
      % (args.law, 100 * (theta_b[-1] / a["link_angle_deg"][-1] - 1),
         100 * np.max(np.abs(theta_b / a["link_angle_deg"] - 1))))
print("at equal rotation: moment %s / neo-Hookean - 1: %+.2f %% .. %+.2f %% (%.1f to %.1f deg)"
      % (args.law, 100 * np.min(moment_b[ok] / a["moment"][ok] - 1), 100 * np.max(moment_b[ok] / a["moment"][ok] - 1),
         a["link_angle_deg"][ok][0], a["link_angle_deg"][ok][-1]))
print("peak principal strain at equal rotation: %s / neo-Hookean - 1: %+.2f %% .. %+.2f %%"
      % (args.law, 100 * np.min(strain_b_at_theta[ok] / a["max_principal_strain_in_body"][ok] - 1),
         100 * np.max(strain_b_at_theta[ok] / a["max_principal_strain_in_body"][ok] - 1)))
print("peak principal strain at equal moment (end): %+.2f %%"
      % (100 * (strain_b[-1] / a["max_principal_strain_in_body"][-1] - 1)))
if args.out:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (m, s) = plt.subplots(1, 2, figsize=(10, 4))
    for name, r in runs.items():
        m.plot(r["link_angle_deg"], r["moment"], "o-", ms=3, label=name)
        s.plot(r["link_angle_deg"], r["max_principal_strain_in_body"], "o-", ms=3, label=name)
    m.set_xlabel("link rotation (deg)"), m.set_ylabel("moment (N mm / mm)"), m.legend(), m.grid(alpha=0.3)
    s.set_xlabel("link rotation (deg)"), s.set_ylabel("peak principal strain"), s.legend(), s.grid(alpha=0.3)
    fig.suptitle("TPU flexure hinge l/t = 10: fitted %s against neo-Hookean (same small-strain G)" % args.law)
    fig.tight_layout()
    fig.savefig(args.out, dpi=110)
    print("chart:", args.out)
