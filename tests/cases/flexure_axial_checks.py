#!/usr/bin/python3
"""A flexure's end-moment stiffness under axial load at finite strain against beam-column theory.

    flexure_axial_checks.py CASE   (cases/verification/flexure_axial_load.prm)

The slender cantilever (L/H = 40, plane strain with nu = 0, so the beam's uniaxial law) carries a dead
axial end force P and an end moment M = 2e-3 on a rigid end face. Reference (computed here, not by the
solver's registry): M / theta = (EI/L) kL / tan kL in compression, (EI/L) kL / tanh kL in tension,
k = sqrt(|P| / EI) (Timoshenko and Gere, Theory of Elastic Stability, sec. 1.5). Issue 27 asks for 1 %
at 0.5 and 0.9 P_cr in compression and P_cr in tension; measured +0.004, -0.019, -0.015 %, so the bar
here is 0.1 %. What the beam model leaves out (shear, about 0.03 % of the buckling load at this
slenderness, amplified ninefold at 0.9 P_cr; the end rotation's square) stays below it. The README's
figures themselves (+0.004, -0.019, -0.015 %) are asserted to 3 units of their last digit (0.003 %).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import run_case  # noqa: E402
from case_checks import check, finish  # noqa: E402

case = sys.argv[1]
E, L, H, M = 1000.0, 40.0, 1.0, 2e-3
EI = E * H ** 3 / 12
critical = math.pi ** 2 * EI / (4 * L ** 2)
for fraction, figure in ((0.5, 0.00004), (0.9, -0.00019), (-1.0, -0.00015)):
    P = fraction * critical
    kL = math.sqrt(abs(P) / EI) * L
    reference = EI / L * (kL / math.tan(kL) if P > 0 else kL / math.tanh(kL))
    q = run_case(case, ["Boundary conditions/Rigid=right: moment=%.17g, force=%.17g 0" % (M, -P),
                        "Comparison/Checks="])["quantities"]
    stiffness = M / q["rigid_rotation_right_z"]
    error = stiffness / reference - 1
    what = "%s %.1f P_cr" % ("compression" if P > 0 else "tension", abs(fraction))
    print("%s: M/theta = %.7g, beam-column %.7g (EI/L = %.7g), %+.3f %%, %d Newton iterations"
          % (what, stiffness, reference, EI / L, 100 * error, q["newton_iterations"]))
    check(abs(error) < 0.001, "%s within 0.1 %% (%+.3f %%)" % (what, 100 * error))
    check(abs(error - figure) <= 0.00003, "%s: %+.4f %% is the README's %+.3f %% (+- 0.003 %%)" % (what, 100 * error, 100 * figure))
finish()
