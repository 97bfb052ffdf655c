"""Formulas for the leaf-spring servo coupling (seed 002) that are not in the closed-form registry:
the paper's own equations as printed, and the project's plate-strip estimate for short leaves in
torsion. Used by postproc/leaf_report.py and tests/cases/leaf_checks.py."""

# The paper (seed 002): Table 1 values it read for a/b = 6, 8, 10, and its reported rotations at
# L = 5 mm under the servo's 2 N m, in the order the text gives them (a = 3, 4, 5 mm).
PAPER_BETA = {3: 0.229, 4: 0.307, 5: 0.313}
PAPER_ROTATION_DEG = {3: 1.5, 4: 2.0, 5: 2.5}
PAPER_E, PAPER_G = 200e3, 80e3   # MPa, as printed
SERVO_TORQUE = 2000.0            # N mm


def paper_stiffness(a, L, b, r):
    """The paper's Eq. 1 and Eq. 2 as printed (N mm/rad): k_E = 12 r^2 E I/L^3, called the total of
    the four leaves (no factor 4), with I = a b^3/12 (thin direction), and k_B = 4 beta a b^3 G/L
    with the paper's beta. Returns (k_E, k_B)."""
    k_E = 12 * r ** 2 * PAPER_E * (a * b ** 3 / 12) / L ** 3
    k_B = 4 * PAPER_BETA[int(round(a))] * a * b ** 3 * PAPER_G / L
    return k_E, k_B


def shear_parameter(L, b, E, nu, kappa=5.0 / 6.0):
    """Timoshenko's Phi = 12 E I/(kappa G A L^2) = E b^2/(kappa G L^2) of a strip of depth b."""
    G = E / (2 * (1 + nu))
    return E * b ** 2 / (kappa * G * L ** 2)


def vlasov_plate_strip(k_saint_venant, k_vlasov, L, b, E, nu, kappa=5.0 / 6.0):
    """Torsional stiffness of a leaf clamped at both ends with Vlasov's warping fibres taken as
    Timoshenko plate strips. Vlasov's excess over G J/L is the bending of the longitudinal fibres
    (for L << a it tends to 12 E Gamma/L^3: the fibre at y is guided-bent by y theta). Their
    deflection is linear in y, so the plate cannot curve anticlastically (E/(1-nu^2)), and a fibre
    only a few thicknesses long also shears (Phi'= Phi/(1-nu^2)): the excess scales by
    (1/(1-nu^2))/(1+Phi') = 1/((1-nu^2) + Phi). The project's own estimate, not a published formula."""
    phi = shear_parameter(L, b, E, nu, kappa)
    return k_saint_venant + (k_vlasov - k_saint_venant) / ((1 - nu ** 2) + phi)
