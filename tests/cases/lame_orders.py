#!/usr/bin/python3
"""Lame's thick cylinder (cases/verification/lame_cylinder.prm, a = 10, b = 20, p = 10, plane strain,
Q2 quarter) at nr x nc = 4 x 8 .. 32 x 64, curved and straight-sided: the README figures that need
more than one mesh. Verification table: the bore displacement u(a) converges at order 1.7, 2.5, 2.8
(curved) and 2.0 (straight-sided) between successive meshes; the straight-sided recovered hoop
stress at the bore is +3.08, +0.865, +0.232 % off at 4 x 8 .. 16 x 32. Geometry: at 8 x 16 the
curved u(a) is 210 times more accurate than the straight-sided one. The single-mesh figures are asserted by case.lame_cylinder_readme_*.

The reference is the closed form u(a) = (1+nu) p a^2/(E (b^2-a^2)) ((1-2nu) a + b^2/a) (nu = 0.3,
E = 1000) and sigma_theta(a) = p (a^2+b^2)/(b^2-a^2); each figure to 3 units of its last digit.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
from study import run_case  # noqa: E402
from case_checks import finish, readme_figure  # noqa: E402

case = os.path.join(here, "..", "..", "cases", "verification", "lame_cylinder.prm")
u_exact = 1.3 * 10 * 100 / (1000 * 300) * (0.4 * 10 + 400 / 10)
hoop_exact = 10 * (100 + 400) / 300
meshes = ((4, 8), (8, 16), (16, 32), (32, 64))
error, hoop = {}, {}
for curved in (True, False):
    for nr, nc in meshes:
        q = run_case(case, ["Geometry/Parameters/nr=%d" % nr, "Geometry/Parameters/nc=%d" % nc,
                            "Discretization/Curved boundaries=%s" % ("true" if curved else "false")])["quantities"]
        error[curved, nr] = q["displacement_inner_x"] / u_exact - 1
        hoop[curved, nr] = q["stress_bore_yy"] / hoop_exact - 1
        print("%s %d x %d: u(a) %+.4e, hoop %+.4e" % ("curved" if curved else "straight", nr, nc,
                                                      error[curved, nr], hoop[curved, nr]))

for curved, figures in ((True, ("1.7", "2.5", "2.8")), (False, ("2.0", "2.0", "2.0"))):
    for (nr, _), figure in zip(meshes[:-1], figures):
        order = math.log2(abs(error[curved, nr] / error[curved, 2 * nr]))
        readme_figure(order, figure, "%s u(a), order from %d to %d cells through the wall"
                      % ("curved" if curved else "straight-sided", nr, 2 * nr))
for (nr, _), figure in zip(meshes[:3], ("3.08", "0.865", "0.232")):
    readme_figure(hoop[False, nr], figure, "straight-sided hoop stress at the bore, %d x %d, %%" % (nr, 2 * nr), 100)
ratio = abs(error[False, 8] / error[True, 8])
readme_figure(ratio, "210", "at 8 x 16, straight-sided u(a) error / curved")
finish()
