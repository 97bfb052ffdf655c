#!/usr/bin/python3
"""Cook's membrane, linear plane stress, degree 2, at 16 x 16, 32 x 32 and 64 x 64 cells (README,
"Where we disagree with the references"): the loaded edge's midpoint (48, 52) 23.9608, 23.9650 at
32 and 64, Richardson-converged 23.968 (FinEtools' 23.96 is checked by case.cook_membrane_linear);
the corner (48, 60) 25.137, 25.164 at 32 and 64, converging at order about 1 to about 25.19.

Verification table, nearly incompressible Cook (plane strain, E = 250, nu = 0.4999, mixed Q2-P1): the
converged 0.074047 and order 1.2 are Richardson on n = 16, 32, 64 (the single meshes are asserted by
case.cook_membrane_mixed*; n = 128 is a one-off run).

Each figure to 3 units of its last printed digit (issue 34). "About 25.19" is asserted to 3 units of
its last digit like the others; "order about 1" (one digit, no decimals) within 0.2.
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
from study import run_case  # noqa: E402
from case_checks import check, finish, readme_figure  # noqa: E402

case = os.path.join(here, "..", "..", "cases", "verification", "cook_membrane_linear.prm")
mid, corner = {}, {}
for n in (16, 32, 64):
    q = run_case(case, ["Geometry/Parameters/n=%d" % n])["quantities"]
    mid[n], corner[n] = q["displacement_mid_y"], q["displacement_corner_y"]
    print("n = %d: midpoint %.7f, corner %.7f" % (n, mid[n], corner[n]))


def richardson(v):
    """Order and extrapolated value from three meshes halving the cell size."""
    ratio = (v[32] - v[16]) / (v[64] - v[32])
    return math.log2(ratio), v[64] + (v[64] - v[32]) / (ratio - 1)


readme_figure(mid[32], "23.9608", "midpoint at 32 x 32")
readme_figure(mid[64], "23.9650", "midpoint at 64 x 64")
order, converged = richardson(mid)
readme_figure(converged, "23.968", "midpoint converged (Richardson on 16, 32, 64; order %.2f)" % order)
readme_figure(corner[32], "25.137", "corner at 32 x 32")
readme_figure(corner[64], "25.164", "corner at 64 x 64")
order, converged = richardson(corner)
check(abs(order - 1) < 0.2, "corner converges at order %.2f, the README's about 1 (+- 0.2)" % order)
readme_figure(converged, "25.19", "corner converged (Richardson on 16, 32, 64)")

mixed = {}
for n in (16, 32, 64):
    mixed[n] = run_case(case, ["Model=plane strain", "Material/Materials=*: steel, E=250, nu=0.4999",
                               "Geometry/Parameters/n=%d" % n, "Discretization/Formulation=mixed"])["quantities"]["displacement_mid_y"]
    print("nearly incompressible, mixed, n = %d: midpoint %.8f" % (n, mixed[n]))
order, converged = richardson(mixed)
readme_figure(order, "1.2", "nearly incompressible, mixed: observed order")
readme_figure(converged, "0.074047", "nearly incompressible, mixed: converged (Richardson on 16, 32, 64)")
finish()
