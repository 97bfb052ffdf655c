"""Incompressible hyperelastic laws in the three standard tests, for fitting (fit_material.py).

Written apart from the solver's law (solver/fe/finite_strain/hyperelastic_law*.cc, which works with
tensors of a compressible material): here each law is a closed form of the principal stretches, so a
finite-element run of a fitted law checks one computation against another.

Nominal (first Piola-Kirchhoff) stress P against the stretch lam of the test direction:
  uniaxial     stretches (lam, lam^-1/2, lam^-1/2)
  equibiaxial  (lam, lam, lam^-2)
  planar       (lam, 1, 1/lam)       (pure shear)
Laws (the solver's constants and names, 'Finite strain/Law constants'):
  neo-Hookean   W = C10 (I1-3)
  Mooney-Rivlin W = C10 (I1-3) + C01 (I2-3)
  Yeoh          W = C10 (I1-3) + C20 (I1-3)^2 + C30 (I1-3)^3
  Ogden N       W = sum_p 2 mu_p/alpha_p^2 (l1^a_p + l2^a_p + l3^a_p - 3)   (Ogden 1972, Abaqus)
Invariant laws: sigma_i - sigma_j = 2 (l_i^2 - l_j^2) (W1 + l_k^2 W2) (Ogden, Non-linear Elastic
Deformations, 1984, sec. 7.2); Ogden: sigma_i = sum_p 2 mu_p/alpha_p l_i^alpha_p - p.
"""
import numpy as np

MODES = ("uniaxial", "planar", "equibiaxial")
INVARIANT_LAWS = {"neo-Hookean": ("C10",), "Mooney-Rivlin": ("C10", "C01"), "Yeoh": ("C10", "C20", "C30")}


def stretches(mode, lam):
    """Principal stretches (3, n) of the incompressible test."""
    lam = np.asarray(lam, dtype=float)
    if mode == "uniaxial":
        return np.array([lam, lam ** -0.5, lam ** -0.5])
    if mode == "equibiaxial":
        return np.array([lam, lam, lam ** -2.0])
    if mode == "planar":
        return np.array([lam, np.ones_like(lam), 1.0 / lam])
    raise ValueError(f"unknown test mode {mode!r}; expected one of {MODES}")


def invariant_basis(law, mode, lam):
    """Columns: the nominal stress per unit constant (invariant laws are linear in them)."""
    l1, l2, l3 = stretches(mode, lam)
    I1 = l1 ** 2 + l2 ** 2 + l3 ** 2
    # P = (sigma_1 - sigma_3) / lam with sigma_3 = 0 (uniaxial, equibiaxial) or the free face
    # (planar: direction 3 is stress-free), direction k the remaining one
    lk2 = l2 ** 2
    factor = 2 * (l1 ** 2 - l3 ** 2) / lam
    columns = {"C10": factor, "C01": factor * lk2}
    x = I1 - 3
    columns["C20"] = factor * 2 * x
    columns["C30"] = factor * 3 * x ** 2
    return np.column_stack([columns[name] for name in INVARIANT_LAWS[law]])


def ogden_basis(alpha, mode, lam):
    """Columns: the nominal stress per unit mu_p for the exponents alpha."""
    l1, _, l3 = stretches(mode, lam)
    return np.column_stack([2.0 / a * (l1 ** a - l3 ** a) / lam for a in alpha])


def nominal_stress(law, constants, mode, lam):
    """P(lam) of a law; constants as a dict of the solver's names (mu1, alpha1, ... or C10, ...)."""
    if law == "Ogden":
        n = len([k for k in constants if k.startswith("mu")])
        mu = np.array([constants[f"mu{p}"] for p in range(1, n + 1)])
        alpha = [constants[f"alpha{p}"] for p in range(1, n + 1)]
        return ogden_basis(alpha, mode, lam) @ mu
    c = np.array([constants[name] for name in INVARIANT_LAWS[law]])
    return invariant_basis(law, mode, lam) @ c


def shear_modulus(law, constants):
    if law == "Ogden":
        return sum(v for k, v in constants.items() if k.startswith("mu"))
    return 2 * (constants["C10"] + constants.get("C01", 0.0))


def log_strain_hessian(law, constants, eps):
    """d2W/d eps_i d eps_j of the incompressible law at principal log strains eps (3,)."""
    eps = np.asarray(eps, dtype=float)
    if law == "Ogden":
        n = len([k for k in constants if k.startswith("mu")])
        h = sum(2 * constants[f"mu{p}"] * np.exp(constants[f"alpha{p}"] * eps) for p in range(1, n + 1))
        return np.diag(h)
    l2 = np.exp(2 * eps)
    x = l2.sum() - 3
    W1 = constants["C10"] + 2 * constants.get("C20", 0.0) * x + 3 * constants.get("C30", 0.0) * x ** 2
    W2 = constants.get("C01", 0.0)
    W11 = 2 * constants.get("C20", 0.0) + 6 * constants.get("C30", 0.0) * x
    return W11 * 4 * np.outer(l2, l2) + np.diag(4 * l2 * W1 + 4 / l2 * W2)


def drucker_violation(law, constants, lo=0.1, hi=10.0, n=401):
    """'' if d tau : d eps > 0 for every isochoric increment along the three tests with the stretch
    in [lo, hi] (Abaqus's check, 0.1 to 10); else the first test and stretch where it fails."""
    q = np.array([[1, -1, 0] / np.sqrt(2), [1, 1, -2] / np.sqrt(6)])
    for mode in ("uniaxial", "equibiaxial", "planar"):
        for e in np.linspace(np.log(lo), np.log(hi), n):
            eps = np.log(stretches(mode, np.exp(e))).ravel()
            M = q @ log_strain_hessian(law, constants, eps) @ q.T
            if not (M[0, 0] > 0 and np.linalg.det(M) > 0):
                return f"{mode} stretch {np.exp(e):.4g}"
    return ""
