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

The same cantilever under the axial force and a small transverse end force F is half of a fixed-guided
blade of length 2 L (a parallel-guided flexure's blade): its midpoint is an inflection point, so the
guided stiffness is F / (2 v_tip). Reference (computed here): the exact beam-column (E I / l^3) q^3 sin q
/ (2 (1 - cos q) - q sin q), sinh/cosh in tension, l = 2 L; the beam constraint model (Awtar et al.
2007), 12 + 6/5 p - p^2/700, beside it where |p| <= 5. Measured -0.032, -0.062, -0.053 % from the exact
(shear: 12 E I / (kappa G A l^2) = 0.04 % here), bar 0.1 %; the BCM -0.066 % and +0.004 %.
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

F, l = 1e-5, 2 * L
for fraction, figure in ((0.5, -0.00032), (0.9, -0.00062), (-1.0, -0.00053)):
    P = fraction * critical
    q_ = math.sqrt(abs(P) / EI) * l
    exact = EI / l ** 3 * (q_ ** 3 * math.sin(q_) / (2 * (1 - math.cos(q_)) - q_ * math.sin(q_)) if P > 0 else
                           q_ ** 3 * math.sinh(q_) / (q_ * math.sinh(q_) - 2 * (math.cosh(q_) - 1)))
    p = -P * l ** 2 / EI
    bcm = EI / l ** 3 * (12 + 1.2 * p - p * p / 700)
    q = run_case(case, ["Boundary conditions/Rigid=right: force=%.17g %.17g" % (-P, F), "Comparison/Checks="])["quantities"]
    stiffness = F / (2 * q["rigid_displacement_right_y"])
    error = stiffness / exact - 1
    what = "guided blade, %s %.1f P_cr" % ("compression" if P > 0 else "tension", abs(fraction))
    print("%s: F/delta = %.7g, beam-column %.7g, BCM %.7g (p = %.3g): %+.3f %%, BCM %+.3f %%"
          % (what, stiffness, exact, bcm, p, 100 * error, 100 * (stiffness / bcm - 1)))
    check(abs(error) < 0.001, "%s within 0.1 %% of the exact beam-column (%+.3f %%)" % (what, 100 * error))
    check(abs(error - figure) <= 0.00003, "%s: %+.4f %% is the README's %+.3f %% (+- 0.003 %%)" % (what, 100 * error, 100 * figure))
    if abs(p) <= 5:
        check(abs(stiffness / bcm - 1) < 0.001, "%s: the beam constraint model within 0.1 %% (%+.3f %%)"
              % (what, 100 * (stiffness / bcm - 1)))
    # README: the BCM -0.066 % at p = -4.9 and -1.1 % at p = -8.9 (beyond its |p| <= 5), to 3 units.
    bcm_figure = {0.5: (-0.00066, 0.00003), 0.9: (-0.011, 0.003)}.get(fraction)
    if bcm_figure:
        check(abs(stiffness / bcm - 1 - bcm_figure[0]) <= bcm_figure[1], "%s: the BCM %+.4f %% is the README's %+.3g %% (+- %.2g %%)"
              % (what, 100 * (stiffness / bcm - 1), 100 * bcm_figure[0], 100 * bcm_figure[1]))
finish()
