"""Helpers of the contact checks (contact_checks.py, contact_pair_checks.py): a run with its
curve.csv and contact.csv, the penetration bar, and the Hertz fits of nodal contact forces."""
import csv
import math
import os
import shutil
import sys
import tempfile

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "postproc"))
from study import run_case  # noqa: E402
from case_checks import check  # noqa: E402


def run_with_files(case, sets=(), np=2, fields=None):
    """Runs a case; returns (quantities, rows of curve.csv, rows of contact.csv). fields: a dict
    that gets the written fields' nodes and contact_pressure and contact_gap (fields.h5)."""
    out = tempfile.mkdtemp(prefix="compliant-contact-")
    try:
        sets = list(sets) + (["Output/Fields=true"] if fields is not None else [])
        q = run_case(case, sets, np=np, output_dir=out)["quantities"]
        with open(os.path.join(out, "curve.csv")) as f:
            curve = list(csv.DictReader(f))
        nodes = []
        if os.path.exists(os.path.join(out, "contact.csv")):
            with open(os.path.join(out, "contact.csv")) as f:
                nodes = list(csv.DictReader(f))
        if fields is not None:
            import h5py
            with h5py.File(os.path.join(out, "fields.h5"), "r") as f:
                for name in ("nodes", "contact_pressure", "contact_gap"):
                    if name in f:
                        fields[name] = [list(row) if hasattr(row, "__len__") else row for row in f[name][()]]
        return q, curve, nodes
    finally:
        shutil.rmtree(out, ignore_errors=True)


def fields_match_nodes(fields, nodes, what):
    """The contact pressure and gap fields equal contact.csv at every contact node (the fields are
    single precision: to 1e-6 of the largest value)."""
    if not check("contact_pressure" in fields and "contact_gap" in fields,
                 "%s: fields.h5 holds contact_pressure and contact_gap" % what):
        return
    xyz = fields["nodes"]
    scale = {k: max(abs(float(n[k])) for n in nodes) for k in ("pressure", "gap")}
    worst = {"pressure": 0.0, "gap": 0.0}
    for n in nodes:
        ref = [float(n["reference_" + a]) for a in "xyz" if "reference_" + a in n]
        k = min(range(len(xyz)), key=lambda i: sum((xyz[i][d] - ref[d]) ** 2 for d in range(len(ref))))
        for key, field in (("pressure", "contact_pressure"), ("gap", "contact_gap")):
            value = fields[field][k]
            value = value[0] if isinstance(value, list) else value
            worst[key] = max(worst[key], abs(value - float(n[key])))
    for key in worst:
        check(worst[key] <= 1e-6 * scale[key], "%s: the contact_%s field equals contact.csv at all %d nodes (to %.2g, "
              "largest %.3g)" % (what, key, len(nodes), worst[key], scale[key]))


def no_penetration(q, nodes, what):
    """The stated tolerance holds: at every node (contact.csv) and in the summary."""
    tol = q["contact_penetration_tolerance"]
    # (A slave node of a pair with no master surface behind it has no gap: nan.)
    deepest = max(-float(n["gap"]) for n in nodes if not math.isnan(float(n["gap"])))
    held = [abs(float(n["gap"])) for n in nodes if n["obstacle"]]
    check(q["contact_max_penetration"] <= tol and deepest <= tol,
          "%s: no node deeper than the tolerance %.3g (deepest %.3g, summary %.3g)"
          % (what, tol, deepest, q["contact_max_penetration"]))
    check(max(held) <= tol, "%s: every held node on the obstacle within the tolerance (largest gap %.3g)"
          % (what, max(held)))


def hertz_fit(nodes):
    """Contact pressure at the nodes on the plane from their forces and the deformed positions
    (Q1: a node carries half of each segment beside it; the symmetry node half of one), and the
    Hertz ellipse p^2 = p0^2 (1 - x^2 / b^2) fitted to the nodes inside the contact (the last
    held node, cut by the edge, left out). Returns (b, p0 fitted, p at x = 0, held nodes)."""
    rows = sorted(nodes, key=lambda n: float(n["x"]))
    x = [float(n["x"]) for n in rows]
    force = [float(n["force"]) for n in rows]
    held = [i for i, n in enumerate(rows) if n["obstacle"]]
    pressure = []
    for i in range(len(rows) - 1):
        width = (x[i + 1] - x[i]) / 2 + ((x[i] - x[i - 1]) / 2 if i > 0 else 0)
        pressure.append(force[i] / width)
    inside = held[:-1]
    n = len(inside)
    sx = sum(x[i] ** 2 for i in inside)
    sy = sum(pressure[i] ** 2 for i in inside)
    sxx = sum(x[i] ** 4 for i in inside)
    sxy = sum(x[i] ** 2 * pressure[i] ** 2 for i in inside)
    slope = (n * sxy - sx * sy) / (n * sxx - sx ** 2)
    intercept = (sy - slope * sx) / n
    return math.sqrt(-intercept / slope), math.sqrt(intercept), pressure[0], len(held)


def hertz_sphere_fit(nodes, inner=0.8):
    """The Hertz ellipsoid p^2 = p0^2 (1 - rho^2 / a^2) fitted (least squares in rho^2) to the held
    nodes of the top face within `inner` of the outermost held node's radius (the ring cut by the
    contact's edge carries part of a tributary area in contact, part not). The pressure is
    contact.csv's (nodal force over the node's share of the face). Returns (a, p0 fitted, p at the
    origin, held nodes)."""
    held = [n for n in nodes if n["obstacle"]]
    rho = lambda n: math.hypot(float(n["x"]), float(n["y"]))  # noqa: E731
    edge = max(rho(n) for n in held)
    inside = [n for n in held if rho(n) <= inner * edge]
    xs = [rho(n) ** 2 for n in inside]
    ys = [float(n["pressure"]) ** 2 for n in inside]
    k = len(inside)
    sx, sy = sum(xs), sum(ys)
    sxx, sxy = sum(x * x for x in xs), sum(x * y for x, y in zip(xs, ys))
    slope = (k * sxy - sx * sy) / (k * sxx - sx ** 2)
    intercept = (sy - slope * sx) / k
    centre = min(held, key=rho)
    return math.sqrt(-intercept / slope), math.sqrt(intercept), float(centre["pressure"]), len(held)
