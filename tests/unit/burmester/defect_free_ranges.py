#!/usr/bin/python3
"""The README's description of the defect-free four-bars without a lower link bound (Morphing-wing
four-bar): links of 0.0015-0.008 chord, within 0.02-2.65 degrees of transmission angle and at most
0.35 degrees of input rotation of a toggle. Read from OUT/candidates.csv (rows with defect 'none',
whose verdicts check_defect_verdicts.py confirms independently) and compared at the digits printed.
Usage: defect_free_ranges.py OUT"""
import csv
import os
import sys

if len(sys.argv) != 2:
    sys.exit("usage: defect_free_ranges.py OUT")
rows = [r for r in csv.DictReader(open(os.path.join(sys.argv[1], "candidates.csv"))) if r["defect"] == "none"]
if not rows:
    sys.exit("FAIL: no defect-free candidate in " + sys.argv[1])
links = [float(r[k]) for r in rows for k in ("ground", "input", "coupler", "output")]
mu = [float(r["toggle_margin_mu_deg"]) for r in rows]
turn = [float(r["toggle_margin_input_deg"]) for r in rows]
found = (round(min(links), 4), round(max(links), 3), round(min(mu), 2), round(max(mu), 2), round(max(turn), 2))
readme = (0.0015, 0.008, 0.02, 2.65, 0.35)
print("%d defect-free: links %.5f-%.5f chord, toggle margin %.4f-%.4f deg of transmission angle, at most %.4f deg of input"
      % (len(rows), min(links), max(links), min(mu), max(mu), max(turn)))
if found != readme:
    sys.exit("FAIL: %s rounded as the README prints them, against the README's %s" % (found, readme))
print("PASS")
