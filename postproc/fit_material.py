#!/usr/bin/python3
"""fit_material: fit hyperelastic laws to test data and write the material entry the solver uses.

  /usr/bin/python3 postproc/fit_material.py --uniaxial u.csv [--planar p.csv] [--equibiaxial e.csv]
      [--nu 0.48] [--name semiflex_fit] [--density 1221.6] [--yield 22e6] [--out-dir DIR]

Each CSV: engineering (nominal) strain and nominal stress, one point a line, in the first two
columns; '#' lines are comments (the source), a non-numeric first line is a header. Stress unit:
--stress-unit (MPa by default). Fits neo-Hookean, Mooney-Rivlin, Yeoh and Ogden with 1, 2 and 3
terms by least squares on the nominal stress of all given tests (the closed forms of
hyperelastic_modes.py, incompressible), checks each for Drucker stability (uniaxial, equibiaxial,
planar stretch 0.1 to 10, as the solver does; an unstable fit is redone with its constants held
non-negative, which makes it stable), prints the errors and the small-strain G, E = 2 G (1 + nu)
and nu, and writes to --out-dir: fit.json, material_entry.txt (a library.dat line and the
'Finite strain' lines of a case file per law, constants in MPa for mm-N-MPa cases) and fit.png
(data against every law). Exit 2 on bad input.
"""
import argparse
import itertools
import json
import os
import sys

import numpy as np
from scipy.optimize import least_squares, lsq_linear, nnls

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import hyperelastic_modes as modes  # noqa: E402

LAWS = ("neo-Hookean", "Mooney-Rivlin", "Yeoh", "Ogden 1", "Ogden 2", "Ogden 3")


class InputError(Exception):
    pass


def read_test(path, mode, max_strain=np.inf):
    """(strain, stress) arrays of one test file."""
    strain, stress = [], []
    try:
        lines = open(path).read().splitlines()
    except OSError as e:
        raise InputError(f"--{mode}: cannot read '{path}': {e.strerror}")
    for number, line in enumerate(lines, 1):
        text = line.split("#")[0].strip()
        if not text:
            continue
        fields = [f for f in text.replace(";", ",").replace("\t", ",").split(",") if f.strip()]
        if len(fields) == 1:
            fields = text.split()
        try:
            e, s = float(fields[0]), float(fields[1])
        except (ValueError, IndexError):
            if not strain and number == next(i for i, l in enumerate(lines, 1) if l.split("#")[0].strip()):
                continue  # the header
            raise InputError(f"{path}:{number}: expected 'strain, stress' numbers, got '{line.strip()}'")
        if not (np.isfinite(e) and np.isfinite(s)) or e <= -1:
            raise InputError(f"{path}:{number}: strain must be > -1 and both finite, got '{line.strip()}'")
        if e <= max_strain:
            strain.append(e)
            stress.append(s)
    if len(strain) < 3:
        raise InputError(f"{path}: needs at least 3 data points (up to --max-strain), has {len(strain)}")
    return np.array(strain), np.array(stress)


def linear_fit(law, data, nonnegative=False):
    A = np.vstack([modes.invariant_basis(law, mode, 1 + e) for mode, (e, s) in data.items()])
    b = np.concatenate([s for e, s in data.values()])
    if nonnegative:
        c = lsq_linear(A, b, bounds=(0, np.inf), method="bvls", tol=1e-15).x
    else:
        c = np.linalg.lstsq(A, b, rcond=None)[0]
    return dict(zip(modes.INVARIANT_LAWS[law], (float(v) for v in c)))


def ogden_mu(alpha, data, nonnegative):
    """The best mu for fixed exponents (the law is linear in mu: variable projection)."""
    A = np.vstack([modes.ogden_basis(alpha, mode, 1 + e) for mode, (e, s) in data.items()])
    b = np.concatenate([s for e, s in data.values()])
    if nonnegative:
        return nnls(A, b)[0], A, b
    return np.linalg.lstsq(A, b, rcond=None)[0], A, b


def ogden_fit(n, data, nonnegative=False):
    scale = max(np.abs(s).max() for e, s in data.values())

    def residual(alpha):
        if np.any(np.abs(alpha) < 1e-3):
            return np.full(sum(len(s) for e, s in data.values()), 1e3)
        mu, A, b = ogden_mu(alpha, data, nonnegative)
        return (A @ mu - b) / scale

    best = None
    starts = [-4.0, -2.0, 1.0, 2.5, 5.0, 9.0]
    for start in itertools.combinations(starts, n):
        try:
            fit = least_squares(residual, np.array(start), xtol=1e-15, ftol=1e-15, gtol=1e-15,
                                max_nfev=4000, bounds=(-30, 30))
        except ValueError:
            continue
        if best is None or fit.cost < best.cost:
            best = fit
    alpha = best.x
    mu = ogden_mu(alpha, data, nonnegative)[0]
    order = np.argsort(alpha)
    constants = {}
    for p, i in enumerate(order, 1):
        constants[f"mu{p}"] = float(mu[i])
        constants[f"alpha{p}"] = float(alpha[i])
    return constants


def fit_law(name, data):
    """(law, constants, note): unconstrained, or constrained if that is not Drucker-stable."""
    law = "Ogden" if name.startswith("Ogden") else name
    fit = (lambda nonneg: ogden_fit(int(name.split()[1]), data, nonneg)) if law == "Ogden" else \
        (lambda nonneg: linear_fit(law, data, nonneg))
    constants = fit(False)
    unstable = modes.drucker_violation(law, constants)
    note, stable = "stable", True
    if unstable:
        constants = fit(True)
        again = modes.drucker_violation(law, constants)
        stable = not again
        note = f"unconstrained fit unstable ({unstable}); refit with constants >= 0: " + \
            ("stable" if stable else f"still unstable ({again})")
    return law, constants, note, stable


def errors(law, constants, data):
    residuals = np.concatenate([modes.nominal_stress(law, constants, mode, 1 + e) - s
                                for mode, (e, s) in data.items()])
    peak = max(np.abs(s).max() for e, s in data.values())
    return {"rms": float(np.sqrt(np.mean(residuals ** 2))), "max": float(np.abs(residuals).max()),
            "rms_relative": float(np.sqrt(np.mean(residuals ** 2)) / peak)}


def constants_text(constants, factor):
    return ", ".join(f"{k}={v * factor:.10g}" if not k.startswith("alpha") else f"{k}={v:.10g}"
                     for k, v in constants.items())


def write_entry(path, results, args, to_pa, to_mpa):
    with open(path, "w") as f:
        f.write(f"# fit_material entry for '{args.name}' from {', '.join(args.sources)}\n")
        f.write("# library.dat line (SI; E = 2 G (1 + nu) of the chosen law's small-strain G):\n")
        best = min((r for r in results if r["stable"]), key=lambda r: r["errors"]["rms"])
        E = 2 * best["G"] * to_pa * (1 + args.nu)
        f.write(f"{args.name:<21} {E:.6g}  {args.nu:g}  {args.density:g}  {args.yield_strength:g}  "
                f"{args.source or 'fit_material'}; {best['name']} fit (E from its G)\n\n")
        for r in results:
            f.write(f"# {r['name']}: rms error {r['errors']['rms']:.4g} {args.stress_unit} "
                    f"({100 * r['errors']['rms_relative']:.3g} % of the peak stress), {r['drucker']}\n")
            f.write("subsection Finite strain\n")
            f.write(f"  set Law = {r['law']}\n")
            f.write(f"  set Law constants = {constants_text(r['constants'], to_mpa)}\n")
            f.write("end\n\n")
    return best


def chart(path, data, results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(data), figsize=(5.2 * len(data), 4.2), squeeze=False)
    for ax, (mode, (e, s)) in zip(axes[0], data.items()):
        ax.plot(e, s, "ko", ms=4, label="data")
        grid = np.linspace(min(0.0, e.min()), e.max(), 200)
        for r in results:
            ax.plot(grid, modes.nominal_stress(r["law"], r["constants"], mode, 1 + grid),
                    label=f"{r['name']} (rms {r['errors']['rms']:.3g})")
        ax.set_title(mode)
        ax.set_xlabel("nominal strain")
        ax.set_ylabel("nominal stress")
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    for mode in modes.MODES:
        parser.add_argument(f"--{mode}", help=f"{mode} test CSV (strain, nominal stress)")
    parser.add_argument("--max-strain", type=float, default=np.inf,
                        help="fit only points up to this nominal strain (all tests); default: all")
    parser.add_argument("--stress-unit", default="MPa", choices=("MPa", "Pa"))
    parser.add_argument("--nu", type=float, default=0.48,
                        help="Poisson's ratio for the entry (the solver's bulk modulus); default 0.48")
    parser.add_argument("--name", default="fitted_material")
    parser.add_argument("--density", type=float, default=0.0, help="kg/m^3, for the library line")
    parser.add_argument("--yield", dest="yield_strength", type=float, default=0.0, help="Pa, for the library line")
    parser.add_argument("--source", default="", help="source text for the library line")
    parser.add_argument("--laws", default=",".join(LAWS), help="comma list of " + ", ".join(LAWS))
    parser.add_argument("--out-dir", default="fit_material_out")
    parser.add_argument("--no-chart", action="store_true")
    args = parser.parse_args(argv)
    try:
        if not args.uniaxial:
            raise InputError("--uniaxial: a uniaxial test CSV is required")
        if not (-1 < args.nu < 0.5):
            raise InputError(f"--nu: expected -1 < nu < 0.5, got {args.nu}")
        names = [n.strip() for n in args.laws.split(",")]
        for n in names:
            if n not in LAWS:
                raise InputError(f"--laws: unknown law '{n}'; expected some of {', '.join(LAWS)}")
        data = {mode: read_test(getattr(args, mode), mode, args.max_strain) for mode in modes.MODES if getattr(args, mode)}
    except InputError as e:
        print(f"fit_material: {e}", file=sys.stderr)
        return 2
    args.sources = [getattr(args, m) for m in data]
    to_pa = 1e6 if args.stress_unit == "MPa" else 1.0
    to_mpa = to_pa * 1e-6
    results = []
    for name in names:
        law, constants, note, stable = fit_law(name, data)
        G = modes.shear_modulus(law, constants)
        results.append({"name": name, "law": law, "constants": constants, "drucker": note, "stable": stable,
                        "errors": errors(law, constants, data), "G": G, "E": 2 * G * (1 + args.nu),
                        "E_incompressible": 3 * G, "nu": args.nu})
    print(f"{'law':<14} {'rms':>10} {'max':>10} {'rms/peak':>9} {'G':>10} {'E':>10} {'nu':>5}  "
          f"Drucker / constants ({args.stress_unit})")
    for r in results:
        print(f"{r['name']:<14} {r['errors']['rms']:10.4g} {r['errors']['max']:10.4g} "
              f"{100 * r['errors']['rms_relative']:8.3g}% {r['G']:10.4g} {r['E']:10.4g} {r['nu']:5.3g}  "
              f"{r['drucker']}: {constants_text(r['constants'], 1.0)}")
    print(f"(E = 2 G (1 + nu) with nu = {args.nu} given; incompressible E = 3 G)")
    os.makedirs(args.out_dir, exist_ok=True)
    with open(os.path.join(args.out_dir, "fit.json"), "w") as f:
        json.dump({"stress_unit": args.stress_unit, "sources": args.sources, "laws": results}, f, indent=1)
    best = write_entry(os.path.join(args.out_dir, "material_entry.txt"), results, args, to_pa, to_mpa)
    print(f"lowest rms among stable fits: {best['name']}; entry: {os.path.join(args.out_dir, 'material_entry.txt')}")
    if not args.no_chart:
        chart(os.path.join(args.out_dir, "fit.png"), data, results)
        print(f"chart: {os.path.join(args.out_dir, 'fit.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
