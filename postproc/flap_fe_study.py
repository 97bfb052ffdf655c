#!/usr/bin/python3
"""FE of the one-piece compliant flap four-bar against its PRBM (issue 6, items 3 and 5).

    /usr/bin/python3 postproc/flap_fe_study.py [--parts sweep,lengths,fatigue,design] [--np 2]

Needs the solver (COMPLIANT_SOLVER or build/solver/fe/compliant), flap_prbm (FLAP_PRBM or
build/solver/mechanisms/four_bar/flap_prbm) and fatigue_life (FATIGUE_LIFE or
build/solver/fatigue/fatigue_life). For each FE run (cases/flap/flap_fe.prm with the flexure
length lk and thickness t set) it reads curve.csv (one row per load step: crank angle, input
torque = reaction moment on crank_drive about A, peak principal strain per flexure) and runs
flap_prbm with the same E, b, h = t and l_k for the quasi-static spring torque of Eq. 12
(T_spring_Nm of the up-sweep of flap_torque_cycle.csv), interpolated to the FE crank angles.

parts:
  lengths  FE vs PRBM for l_k = 4, 2, 1, 0.5 mm at t = 3 mm (paper h), slender flexures
           (l_k/t = 10: 4/0.4, 2/0.2), a mesh check (nt = 8) and the paper design (l_k = 1) with
           near-rigid links (link bodies 1000 x stiffer)
  fatigue  hot-spot strain history of one crank cycle (up and back, harmonic drive, 60 rpm) of
           the paper design -> cases/fatigue/flap_fe_paper_design.csv, fatigue_life --run-out 717727
  design   flexure thickness x length grid (t = 0.5, 1, 2 x l_k = 2, 4, 8 mm): peak input torque
           and predicted life
Runs that hang (a rank failing inside a collective) are killed after 240 s and keep their steps.
Writes CSVs to --out (default results/flap_fe_study), charts (PNG) and FE_REPORT.md to cases/flap/.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study  # noqa: E402  (solver path, MPI environment)

ROOT = study.ROOT
CASE = os.path.join(ROOT, "cases", "flap", "flap_fe.prm")
L1, L2, L3, L4 = 60.0, 10.0, 65.0, 15.0
E_MPA, B_MM = 89.5, 1.5  # semiflex in solver/fe/materials/library.dat; paper Table 1 b
RUN_OUT = 717727
REUSE = False


def tool(env, *parts):
    return os.environ.get(env, os.path.join(ROOT, "build", *parts))


# ---- four-bar kinematics (independent of flap_prbm; checked against it below) ----
def rocker_coupler(th2):
    """Rocker and coupler angles (rad) for crank angle th2, C above AD (flap_prbm 'minus')."""
    bx, by = L2 * math.cos(th2), L2 * math.sin(th2)
    dx, dy = L1 - bx, -by
    d = math.hypot(dx, dy)
    a = (L3 * L3 - L4 * L4 + d * d) / (2 * d)
    h = math.sqrt(max(L3 * L3 - a * a, 0.0))
    px, py = bx + a * dx / d, by + a * dy / d
    c1 = (px - h * dy / d, py + h * dx / d)
    c2 = (px + h * dy / d, py - h * dx / d)
    cx, cy = c1 if c1[1] >= c2[1] else c2
    return math.atan2(cy, cx - L1), math.atan2(cy - by, cx - bx)


def crank_window(sweep_deg=26.0):
    """Crank range that swings the rocker through sweep_deg, centred where the transmission
    angle is 90 deg (cos th2 = (l1^2 + l2^2 - l3^2 - l4^2) / (2 l1 l2)): flap_prbm's reading."""
    centre = math.acos((L1 ** 2 + L2 ** 2 - L3 ** 2 - L4 ** 2) / (2 * L1 * L2))
    lo, hi = 1e-3, 2.0
    for _ in range(200):
        s = 0.5 * (lo + hi)
        swing = abs(rocker_coupler(centre + s / 2)[0] - rocker_coupler(centre - s / 2)[0])
        lo, hi = (s, hi) if swing < math.radians(sweep_deg) else (lo, s)
    s = 0.5 * (lo + hi)
    return math.degrees(centre - s / 2), math.degrees(s)


CRANK0, CRANK_SWEEP = crank_window()
ROCKER0 = math.degrees(rocker_coupler(math.radians(CRANK0))[0])


# ---- runs ----
def run_fe(out, lk, t, extra=(), np=2, label=None, timeout=240):
    """Runs the FE case; returns dict with the curve rows, iterations, steps, run time, status."""
    d = os.path.join(out, "fe_" + (label or "lk%g_t%g" % (lk, t)))
    os.makedirs(d, exist_ok=True)
    cmd = ["mpirun", "-np", str(np), study.solver_path(), CASE, "--set", "Output/Directory=" + d,
           "--set", "Output/Fields=false", "--set", "Geometry/Parameters/lk=%g" % lk,
           "--set", "Geometry/Parameters/t=%g" % t]
    for s in extra:
        cmd += ["--set", s]
    reuse = os.path.join(d, "run.json")
    if REUSE and os.path.exists(reuse):  # --reuse: a finished run of the same settings
        with open(reuse) as f:
            return json.load(f)
    start = time.time()
    # A guard only: a run that hangs or crawls is stopped and the study goes on with the steps
    # converged so far (an MPI hang once seen here, a throw on one rank, is fixed in the solver).
    child = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             env=study.mpi_env(), start_new_session=True)
    try:
        stdout, stderr = child.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(child.pid, 15)  # mpirun and its ranks: their own process group
        stdout, stderr = child.communicate()
        stderr += "\nrun killed after %d s (hung)" % timeout
        child.returncode = -9
    proc = subprocess.CompletedProcess(cmd, child.returncode, stdout, stderr)
    wall = time.time() - start
    with open(os.path.join(d, "log.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n" + proc.stdout + proc.stderr)
    curve_file = os.path.join(d, "curve.csv")
    rows = []
    if os.path.exists(curve_file):
        with open(curve_file) as f:
            rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    summary = {}
    if os.path.exists(os.path.join(d, "summary.json")):
        with open(os.path.join(d, "summary.json")) as f:
            summary = json.load(f)
    status = "completed" if proc.returncode == 0 else "exit %d: %s" % (
        proc.returncode, proc.stderr.strip().splitlines()[-1] if proc.stderr.strip() else "")
    if proc.returncode not in (0, 3, -9):  # e.g. the mesher failed: reported, the study goes on
        status = "failed (exit %d), see %s" % (proc.returncode, os.path.join(d, "log.txt"))
        print("FE run failed:", " ".join(cmd), file=sys.stderr)
    mesh = re.search(r"Mesh: (\d+) cells, (\d+) DoFs", proc.stdout)
    result = {"rows": rows, "wall": wall, "status": status, "lk": lk, "t": t,
            "newton": sum(r["newton_iterations"] for r in rows), "steps": len(rows),
            "cells": int(mesh.group(1)) if mesh else 0, "dofs": int(mesh.group(2)) if mesh else 0,
            "cutbacks": summary.get("quantities", {}).get("step_cutbacks", float("nan"))}
    with open(reuse, "w") as f:
        json.dump(result, f)
    return result


def run_prbm(out, lk, t):
    """flap_prbm quasi-static spring torque (Eq. 12) of the up-sweep: (crank_deg, T_Nm) lists."""
    d = os.path.join(out, "prbm_lk%g_t%g" % (lk, t))
    cmd = [tool("FLAP_PRBM", "solver", "mechanisms", "four_bar", "flap_prbm"),
           os.path.join(ROOT, "cases", "flap", "flap_prbm_default.prm"), "--output", d,
           "--set", "flexure_length_mm=%g" % lk, "--set", "flexure_thickness_mm=%g" % t,
           "--set", "youngs_modulus_mpa=%g" % E_MPA, "--set", "flexure_width_mm=%g" % B_MM]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError("flap_prbm failed: %s\n%s" % (" ".join(cmd), proc.stderr))
    crank, torque, rocker = [], [], []
    with open(os.path.join(d, "flap_torque_cycle.csv")) as f:
        for r in csv.DictReader(f):
            if float(r["motor_deg"]) <= 180:
                crank.append(float(r["crank_deg"]))
                torque.append(float(r["T_spring_Nm"]))
                rocker.append(float(r["rocker_deg"]))
    return crank, torque, rocker


def interp(x, xs, ys):
    """Linear interpolation on increasing xs; the ends are extrapolated from the last interval."""
    if x <= xs[0]:
        i = 0
    elif x >= xs[-1]:
        i = len(xs) - 2
    else:
        i = next(k for k in range(len(xs) - 1) if xs[k] <= x <= xs[k + 1])
    w = (x - xs[i]) / (xs[i + 1] - xs[i])
    return ys[i] + w * (ys[i + 1] - ys[i])


def compare(fe, prbm):
    """Rows of FE against PRBM along the sweep (torque in N m)."""
    pc, pt, _ = prbm
    rows = []
    for r in fe["rows"]:
        crank = r["crank_deg"]
        t_fe, t_prbm = r["input_torque_Nm"], interp(crank, pc, pt)
        flap = math.degrees(rocker_coupler(math.radians(crank))[0]) - ROCKER0
        rows.append({"lk": fe["lk"], "t": fe["t"], "crank_deg": crank, "flap_deg": flap,
                     "load_factor": r["load_factor"], "newton": r["newton_iterations"],
                     "T_fe_Nm": t_fe, "T_prbm_Nm": t_prbm,
                     "diff_pct": 100 * (t_fe / t_prbm - 1) if abs(t_prbm) > 1e-12 else float("nan"),
                     **{"eps_" + h: r["max_principal_strain_in_flexure_" + h] for h in "ABCD"}})
    return rows


def fe_summary(fe, cmp_rows, label):
    end = cmp_rows[-1] if cmp_rows else {}
    peak_fe = max((abs(r["T_fe_Nm"]) for r in cmp_rows), default=float("nan"))
    peak_prbm = max((abs(r["T_prbm_Nm"]) for r in cmp_rows), default=float("nan"))
    return {"series": label, "lk": fe["lk"], "t": fe["t"], "status": fe["status"],
            "flap_reached_deg": end.get("flap_deg", float("nan")),
            "T_fe_end_Nm": end.get("T_fe_Nm", float("nan")),
            "T_prbm_end_Nm": end.get("T_prbm_Nm", float("nan")),
            "diff_end_pct": end.get("diff_pct", float("nan")),
            "peak_T_fe_Nm": peak_fe, "peak_T_prbm_Nm": peak_prbm,
            "diff_peak_pct": 100 * (peak_fe / peak_prbm - 1),
            **{"max_eps_" + h: max((r["eps_" + h] for r in cmp_rows), default=float("nan"))
               for h in "ABCD"},
            "steps": fe["steps"], "newton_total": fe["newton"], "cutbacks": fe["cutbacks"],
            "cells": fe["cells"], "dofs": fe["dofs"], "wall_s": round(fe["wall"], 1)}


def write_csv(path, rows):
    if not rows:
        return
    keys = list(rows[0].keys())
    for r in rows[1:]:
        keys += [k for k in r if k not in keys]
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=keys)
        w.writeheader()
        for r in rows:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in r.items()})


# ---- hot-spot history of one crank cycle and fatigue ----
def cycle_history(fe_rows, path, note):
    """One duty cycle (1 s at 60 rpm): the crank moves harmonically, th2 = th20 + S/2 (1 - cos 2 pi t),
    up then back; the elastic FE state retraces itself on the way back, so the down-sweep reuses
    the up-sweep's steps. Columns: peak lambda_1 - 1 in each flexure."""
    pts = [(0.0, {h: 0.0 for h in "ABCD"})]
    for r in fe_rows:
        lam = min(max(r["load_factor"], 0.0), 1.0)
        pts.append((math.acos(1 - 2 * lam) / (2 * math.pi),
                    {h: max(r["max_principal_strain_in_flexure_" + h], 0.0) for h in "ABCD"}))
    back = [(1.0 - tt, v) for tt, v in reversed(pts[1:-1])] + [(1.0, pts[0][1])]
    with open(path, "w") as f:
        f.write("# generated by postproc/flap_fe_study.py: FE hot-spot histories (peak maximum "
                "principal strain lambda_1 - 1 in each flexure, fraction)\n# %s\n"
                "# one crank cycle at 60 rpm: crank %.4f -> %.4f -> %.4f deg (flap 0 -> 26 -> 0), "
                "harmonic drive\n" % (note, CRANK0, CRANK0 + CRANK_SWEEP, CRANK0))
        f.write("time,flexure_A,flexure_B,flexure_C,flexure_D\n")
        for tt, v in pts + back:
            f.write("%.6f,%s\n" % (tt, ",".join("%.6g" % v[h] for h in "ABCD")))


def run_fatigue(history, report=None, summary_csv=None):
    cmd = [tool("FATIGUE_LIFE", "solver", "fatigue", "fatigue_life"), history,
           "--run-out", str(RUN_OUT)]
    if summary_csv:
        cmd += ["--summary-csv", summary_csv]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError("fatigue_life failed: %s\n%s" % (" ".join(cmd), proc.stderr))
    if report:
        with open(report, "w") as f:
            f.write(proc.stdout)
    text = proc.stdout
    first = text.split("result:")[1]
    crit = re.search(r"critical location: '([^']+)'", first).group(1)
    life = re.search(r"nominal ([0-9.e+inf]+), band ([0-9.e+inf]+) \.\. ([0-9.e+inf]+)", first)
    lifted = text.split("lifted to the run-out")[1] if "lifted to the run-out" in text else first
    life2 = re.search(r"nominal ([0-9.e+inf]+), band ([0-9.e+inf]+) \.\. ([0-9.e+inf]+)", lifted)
    return {"critical": crit, "life_nominal": float(life.group(1)), "life_low": float(life.group(2)),
            "life_high": float(life.group(3)), "life_low_after_run_out": float(life2.group(2))}


# ---- charts ----
def chart_lengths(rows, summaries, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(2, 1, figsize=(8, 8), sharex=True,
                                 gridspec_kw={"height_ratios": [3, 2]})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, s in enumerate(summaries):
        sel = [r for r in rows if r["series"] == s["series"]]
        x = [r["flap_deg"] for r in sel]
        c = colours[i % len(colours)]
        ax.plot(x, [r["T_fe_Nm"] for r in sel], "-o", ms=3, color=c, label="FE " + s["series"])
        ax.plot(x, [r["T_prbm_Nm"] for r in sel], "--", color=c,
                label="PRBM Eq. 12" if i == 0 else None)
        bx.plot([xx for xx, r in zip(x, sel) if r["flap_deg"] > 2],
                [r["diff_pct"] for r in sel if r["flap_deg"] > 2], "-o", ms=3, color=c)
    ax.set_ylabel("input torque on the crank [N m]")
    ax.set_title("Compliant flap: FE (plane stress, finite strain) vs PRBM K = E I / l_k\n"
                 "crank %.2f -> %.2f deg, flap 0 -> 26 deg; dashed: PRBM of the same l_k, t"
                 % (CRANK0, CRANK0 + CRANK_SWEEP), fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    bx.axhline(0, color="k", lw=0.5)
    bx.set_xlabel("flap (rocker) angle from the printed pose [deg]")
    bx.set_ylabel("FE / PRBM - 1 [%]")
    bx.grid(alpha=0.3)
    sec = ax.secondary_xaxis("top", functions=(flap_to_crank, crank_to_flap))
    sec.set_xlabel("crank angle [deg]")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def _crank_flap_table():
    import numpy as np
    cs = np.linspace(CRANK0 - 20, CRANK0 + CRANK_SWEEP + 20, 400)
    return cs, np.array([math.degrees(rocker_coupler(math.radians(v))[0]) - ROCKER0 for v in cs])


def crank_to_flap(c):
    import numpy as np
    cs, fs = _crank_flap_table()
    return np.interp(c, cs, fs)


def flap_to_crank(f):
    import numpy as np
    cs, fs = _crank_flap_table()
    return np.interp(f, fs, cs)


def chart_history(path_csv, path_png, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(path_csv) as f:
        lines = [l for l in f if not l.startswith("#")]
    rows = list(csv.DictReader(lines))
    fig, ax = plt.subplots(figsize=(7, 4))
    for h in "ABCD":
        ax.plot([float(r["time"]) for r in rows], [100 * float(r["flexure_" + h]) for r in rows],
                "-o", ms=2, label="flexure " + h)
    ax.set_xlabel("time [s] (one crank cycle at 60 rpm)")
    ax.set_ylabel("peak max. principal strain [%]")
    ax.set_title(title, fontsize=9)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(path_png, dpi=130)
    plt.close(fig)


def chart_design(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.5))
    ts = sorted({r["t"] for r in rows})
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for i, t in enumerate(ts):
        sel = sorted([r for r in rows if r["t"] == t and r["flap_reached_deg"] > 25.9],
                     key=lambda r: r["lk"])
        c = colours[i % len(colours)]
        ax.plot([r["lk"] for r in sel], [r["peak_T_fe_Nm"] for r in sel], "-o", color=c,
                label="t = %g mm" % t)
        ax.plot([r["lk"] for r in sel], [r["peak_T_prbm_Nm"] for r in sel], "--", color=c)
        x = [r["lk"] for r in sel]
        y = [r["life_nominal"] for r in sel]
        lo = [r["life_nominal"] - r["life_low"] for r in sel]
        hi = [r["life_high"] - r["life_nominal"] for r in sel]
        bx.errorbar(x, y, yerr=[lo, hi], color=c, capsize=3, label="t = %g mm" % t)
        for r in sel:
            ok = r["life_low"] >= 1e6
            nom = r["life_nominal"] >= 1e6
            bx.plot(r["lk"], r["life_nominal"], "o", ms=9, color=c,
                    mfc=c if nom else "white", mew=2 if ok else 1)
    ax.set_xlabel("flexure length l_k [mm]")
    ax.set_ylabel("peak input torque [N m]")
    ax.set_title("peak crank torque over the 26 deg sweep (solid FE, dashed PRBM)", fontsize=9)
    ax.set_yscale("log")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    bx.axhline(1e6, color="g", lw=1, label="target 1e6 cycles")
    bx.axhline(RUN_OUT, color="grey", lw=1, ls=":", label="paper run-out 717,727")
    bx.set_yscale("log")
    bx.set_xlabel("flexure length l_k [mm]")
    bx.set_ylabel("predicted life [cycles] (nominal, band low..high)")
    bx.set_title("filled: nominal life >= 1e6; open: below; thick edge: whole band >= 1e6",
                 fontsize=9)
    bx.legend(fontsize=8)
    bx.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=130)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--parts", default="lengths,fatigue,design")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "flap_fe_study"))
    ap.add_argument("--lengths", default="4,2,1,0.5", help="l_k values at t = 3 mm")
    ap.add_argument("--slender", default="4:0.4,2:0.2", help="l_k:t pairs of slender flexures")
    ap.add_argument("--design-t", default="0.5,1,2")
    ap.add_argument("--design-lk", default="2,4,8")
    ap.add_argument("--set", action="append", default=[], help="extra solver --set for every FE run")
    ap.add_argument("--reuse", action="store_true", help="reuse FE runs already in --out (run.json)")
    args = ap.parse_args()
    global REUSE
    REUSE = args.reuse
    parts = args.parts.split(",")
    os.makedirs(args.out, exist_ok=True)
    flap_dir = os.path.join(ROOT, "cases", "flap")
    results = {"crank0_deg": CRANK0, "crank_sweep_deg": CRANK_SWEEP, "rocker0_deg": ROCKER0}

    # kinematics cross-check against flap_prbm (its rocker angles at the sampled crank angles)
    pc, _, pr = run_prbm(args.out, 1, 3)
    kin_err = max(abs(math.degrees(rocker_coupler(math.radians(c))[0]) - r) for c, r in zip(pc, pr))
    results["kinematics_vs_flap_prbm_max_deg"] = kin_err
    print("crank window %.6f .. %.6f deg (sweep %.6f), rocker %.4f .. %.4f deg; |rocker - flap_prbm| "
          "<= %.2g deg" % (CRANK0, CRANK0 + CRANK_SWEEP, CRANK_SWEEP, ROCKER0, ROCKER0 + 26, kin_err))

    fe_cache = {}

    def fe_and_compare(lk, t, label, extra=()):
        key = (lk, t, tuple(extra))
        if key not in fe_cache:
            fe = run_fe(args.out, lk, t, list(extra) + args.set, args.np,
                        label=None if not extra else label.replace(" ", "_").replace(",", ""))
            cmp_rows = compare(fe, run_prbm(args.out, lk, t))
            for r in cmp_rows:
                r["series"] = label
            fe_cache[key] = (fe, cmp_rows, fe_summary(fe, cmp_rows, label))
            s = fe_cache[key][2]
            print("%-28s flap %5.2f deg  T_end FE %.4g PRBM %.4g N m (%+.1f %%)  peak eps A..D %s  "
                  "%d steps, %d Newton, %.0f s  %s" % (label, s["flap_reached_deg"], s["T_fe_end_Nm"],
                  s["T_prbm_end_Nm"], s["diff_end_pct"], " ".join("%.3f" % s["max_eps_" + h] for h in "ABCD"),
                  s["steps"], s["newton_total"], s["wall_s"], s["status"]), flush=True)
        return fe_cache[key]

    if "lengths" in parts:
        rows, summaries = [], []
        for lk in [float(v) for v in args.lengths.split(",")]:
            fe, cmp_rows, s = fe_and_compare(lk, 3.0, "l_k = %g, t = 3" % lk)
            rows += cmp_rows
            summaries.append(s)
        for pair in args.slender.split(","):
            lk, t = (float(v) for v in pair.split(":"))
            fe, cmp_rows, s = fe_and_compare(lk, t, "l_k = %g, t = %g (l/t = %g)" % (lk, t, lk / t))
            rows += cmp_rows
            summaries.append(s)
        fe, cmp_rows, s = fe_and_compare(1.0, 3.0, "l_k = 1, t = 3, nt = 8",
                                         ["Geometry/Parameters/nt=8", "Geometry/Parameters/hb=1"])
        rows += cmp_rows
        summaries.append(s)
        rigid = ["Material/Materials=*: semiflex; ground_body: semiflex, E=89500; crank: semiflex, "
                 "E=89500; coupler: semiflex, E=89500; rocker: semiflex, E=89500"]
        fe, cmp_rows, s = fe_and_compare(1.0, 3.0, "l_k = 1, t = 3, stiff links", rigid)
        rows += cmp_rows
        summaries.append(s)
        write_csv(os.path.join(args.out, "flap_fe_vs_prbm.csv"), rows)
        write_csv(os.path.join(args.out, "flap_fe_lengths_summary.csv"), summaries)
        chart_lengths(rows, summaries, os.path.join(flap_dir, "flap_fe_vs_prbm.png"))
        results["lengths"] = summaries

    if "fatigue" in parts:
        fe, cmp_rows, s = fe_and_compare(1.0, 3.0, "l_k = 1, t = 3")
        fat_dir = os.path.join(ROOT, "cases", "fatigue")
        hist = os.path.join(fat_dir, "flap_fe_paper_design.csv")
        cycle_history(fe["rows"], hist, "paper design: l_k = 1 mm, t = h = 3 mm, b = 1.5 mm, "
                      "Semiflex E = 89.5 MPa, plane stress, cases/flap/flap_fe.prm")
        life = run_fatigue(hist, os.path.join(fat_dir, "flap_fe_paper_design_report.txt"),
                           os.path.join(fat_dir, "flap_fe_paper_design_summary.csv"))
        chart_history(hist, os.path.join(flap_dir, "flap_fe_hot_spots.png"),
                      "paper design (l_k = 1 mm, t = 3 mm): peak strain per flexure, one cycle")
        print("paper design life: %s" % life)
        results["paper_design_life"] = life
        results["paper_design_fe"] = s

    if "design" in parts:
        design = []
        for t in [float(v) for v in args.design_t.split(",")]:
            for lk in [float(v) for v in args.design_lk.split(",")]:
                fe, cmp_rows, s = fe_and_compare(lk, t, "l_k = %g, t = %g" % (lk, t))
                row = dict(s)
                if s["flap_reached_deg"] > 25.9:
                    hist = os.path.join(args.out, "history_lk%g_t%g.csv" % (lk, t))
                    cycle_history(fe["rows"], hist, "design l_k = %g mm, t = %g mm" % (lk, t))
                    row.update(run_fatigue(hist))
                design.append(row)
        write_csv(os.path.join(args.out, "flap_fe_design.csv"), design)
        chart_design(design, os.path.join(flap_dir, "flap_fe_design.png"))
        results["design"] = design

    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    print("results in", args.out)


if __name__ == "__main__":
    main()
