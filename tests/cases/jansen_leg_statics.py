#!/usr/bin/python3
"""The FE leg (Analysis = linkage) against the statics of ideal pins (cases/jansen/leg_statics.py).

    jansen_leg_statics.py CASE THETA2 [--set "A/B=v"]...

The crank held, the leg is statically determinate: its joint forces follow from equilibrium alone,
so the FE forces must equal the hand check to the solver's round-off whatever the stiffness. The
tolerance 1e-6 (of the largest joint force, and of the ternary links' moment scale for the
moments the pins pass) leaves six orders of margin for round-off and none for a modelling error:
a pin that passed 0.1 % of a link's moment, or a load off H by 0.1 mm, fails it.
"""
import os
import subprocess
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
from study import run_case  # noqa: E402

case, theta2, sets = sys.argv[1], sys.argv[2], []
args = sys.argv[3:]
while args:
    if args[0] == "--set":
        sets.append(args[1])
        args = args[2:]
    else:
        sys.exit("unknown argument " + args[0])
out = tempfile.mkdtemp(prefix="compliant-leg-")
run_case(case, ["Geometry/Parameters/theta2=" + theta2, "Analysis=linkage"] + sets, np=2, output_dir=out)
statics = os.path.join(here, "..", "..", "cases", "jansen", "leg_statics.py")
code = subprocess.run([sys.executable, statics, "--theta2", theta2, "--summary",
                       os.path.join(out, "summary.json"), "--tolerance", "1e-6"]).returncode
subprocess.run(["rm", "-rf", out])
sys.exit(code)
