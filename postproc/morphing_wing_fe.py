#!/usr/bin/python3
"""The morphing-wing spar mechanism as a one-piece compliant part (issue 13, item 5).

    /usr/bin/python3 postproc/morphing_wing_fe.py [--np 2] [--out results/morphing_wing_fe]

The synthesis (burmester_synthesis over cases/morphing_wing/paper_table3.txt) writes the single
revolute joint that carries the spar through the four positions, single_pivot.csv. This study makes
that joint a flexure (cases/morphing_wing/compliant_pivot.prm, meshes/compliant_pivot_arm.geo),
turns the arm by a servo torque at finite strain and reads, at each precision position (the
arm's rotation equal to the position's orientation change):
  - the servo torque against the PRBM of the same flexure, K = E b t^3 / (12 l_k);
  - where the spar point is, against the Table 3 position and against the rigid pivot's point;
  - the flexure's peak principal strain and von Mises stress against the material's strength;
  - the fatigue life of one morphing cycle 1 -> 4 -> 1 (fatigue_life, printed TPU band);
with the mesh refined through the flexure (nt = 2, 4, 8) for convergence. Writes
cases/morphing_wing/compliant_pivot.md (tables) and compliant_pivot.png (chart).
Needs the solver, burmester_synthesis and fatigue_life of a build (COMPLIANT_SOLVER,
BURMESTER_SYNTHESIS, FATIGUE_LIFE override the paths).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import study  # noqa: E402  (solver path, MPI environment)

ROOT = study.ROOT
CASE = os.path.join(ROOT, "cases", "morphing_wing", "compliant_pivot.prm")
POSITIONS = os.path.join(ROOT, "cases", "morphing_wing", "paper_table3.txt")
E_MPA = 89.5      # semiflex, solver/fe/materials/library.dat
STRENGTH = 22.0   # semiflex tensile strength, lower bound (library.dat)


def tool(env, *parts):
    return os.environ.get(env) or os.path.join(ROOT, "build", "solver", *parts)


def case_value(name):
    """A number set in the case file (Geometry/Parameters or Material)."""
    with open(CASE) as f:
        for line in f:
            m = re.match(r"\s*set\s+%s\s*=\s*([-0-9.eE+]+)" % re.escape(name), line)
            if m:
                return float(m.group(1))
    raise KeyError(name)


def single_pivot(out):
    d = os.path.join(out, "synthesis")
    subprocess.run([tool("BURMESTER_SYNTHESIS", "mechanisms", "burmester", "burmester_synthesis"),
                    POSITIONS, d], check=True, capture_output=True, text=True)
    with open(os.path.join(d, "single_pivot.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def run_fe(out, pivot, nt, np):
    d = os.path.join(out, "nt%d" % nt)
    p1 = pivot[0]
    S = "Geometry/Parameters/"
    c = "c*%.10g c*%.10g" % (p1["target_x"], p1["target_y"])
    cmd = ["mpirun", "-np", str(np), study.solver_path(), CASE, "--set", "Output/Directory=" + d,
           "--set", "Output/Fields=false", "--set", S + "nt=%d" % nt,
           "--set", S + "Px=%.10g" % p1["pivot_x"], "--set", S + "Py=%.10g" % p1["pivot_y"],
           "--set", S + "Sx=%.10g" % p1["target_x"], "--set", S + "Sy=%.10g" % p1["target_y"],
           "--set", "Quantities/Points=spar: " + c]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=study.mpi_env())
    if proc.returncode != 0:
        raise RuntimeError("FE run failed: %s\n%s%s" % (" ".join(cmd), proc.stdout[-2000:], proc.stderr))
    with open(os.path.join(d, "curve.csv")) as f:
        rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
    mesh = re.search(r"Mesh: (\d+) cells, (\d+) DoFs", proc.stdout)
    wall = re.search(r"time_total\s+([0-9.e+-]+)", proc.stdout)
    newton = sum(r["newton_iterations"] for r in rows)
    return {"rows": rows, "dofs": int(mesh.group(2)), "time": float(wall.group(1)), "newton": int(newton),
            "steps": len(rows)}


def at_rotation(rows, theta, key):
    """key interpolated (linear, between load steps) where the arm has turned by theta (radians)."""
    pts = [(0.0, 0.0 if key != "load_factor" else 0.0)] + [(r["rigid_rotation_arm_root_z"], r[key]) for r in rows]
    for (x0, y0), (x1, y1) in zip(pts, pts[1:]):
        if min(x0, x1) <= theta <= max(x0, x1) and x1 != x0:
            return y0 + (y1 - y0) * (theta - x0) / (x1 - x0)
    raise ValueError("rotation %g outside the run (%g .. %g)" % (theta, pts[0][0], pts[-1][0]))


def evaluate(fe, pivot, chord, lk, t, b):
    k_prbm = E_MPA * b * t ** 3 / 12 / lk  # N mm / rad
    result = []
    for p in pivot:
        theta = math.radians(p["rotation_deg"])
        if theta == 0:
            result.append({"position": int(p["position"]), "turn_deg": 0.0, "torque": 0.0, "prbm": 0.0,
                           "miss_target": 0.0, "miss_rigid": 0.0, "rigid_miss": 0.0, "strain": 0.0,
                           "mises": 0.0})
            continue
        lam = at_rotation(fe["rows"], theta, "load_factor")
        torque = abs(at_rotation(fe["rows"], theta, "servo_torque_Nmm"))
        ux = at_rotation(fe["rows"], theta, "displacement_spar_x")
        uy = at_rotation(fe["rows"], theta, "displacement_spar_y")
        x = chord * pivot[0]["target_x"] + ux
        y = chord * pivot[0]["target_y"] + uy
        result.append({
            "position": int(p["position"]), "turn_deg": p["rotation_deg"], "load_factor": lam,
            "torque": torque, "prbm": k_prbm * abs(theta),
            "miss_target": math.hypot(x - chord * p["target_x"], y - chord * p["target_y"]),
            "miss_rigid": math.hypot(x - chord * p["rigid_x"], y - chord * p["rigid_y"]),
            "rigid_miss": chord * p["rigid_miss"],
            "strain": at_rotation(fe["rows"], theta, "max_principal_strain_in_flexure"),
            "mises": at_rotation(fe["rows"], theta, "max_von_mises_in_flexure")})
    return result


def fatigue(fe, pivot, out):
    """One morphing cycle: position 1 -> 4 -> 1, harmonic in time; the flexure's peak principal
    strain from the FE steps up to position 4 (the elastic state retraces itself on the way back)."""
    theta4 = math.radians(pivot[-1]["rotation_deg"])
    pts = [(0.0, 0.0)]
    for r in fe["rows"]:
        if abs(r["rigid_rotation_arm_root_z"]) >= abs(theta4):
            break
        s = r["rigid_rotation_arm_root_z"] / theta4
        pts.append((math.acos(1 - 2 * s) / (2 * math.pi), r["max_principal_strain_in_flexure"]))
    pts.append((0.5, at_rotation(fe["rows"], theta4, "max_principal_strain_in_flexure")))
    pts += [(1.0 - tt, v) for tt, v in reversed(pts[:-1])]
    path = os.path.join(out, "morphing_cycle.csv")
    with open(path, "w") as f:
        f.write("# generated by postproc/morphing_wing_fe.py: peak maximum principal strain in the flexure "
                "over one morphing cycle, positions 1 -> 4 -> 1\ntime,flexure\n")
        for tt, v in pts:
            f.write("%.6f,%.6g\n" % (tt, v))
    proc = subprocess.run([tool("FATIGUE_LIFE", "fatigue", "fatigue_life"), path], capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError("fatigue_life failed:\n" + proc.stderr)
    life = re.search(r"nominal ([0-9.e+inf]+), band ([0-9.e+inf]+) \.\. ([0-9.e+inf]+)", proc.stdout)
    return {"nominal": float(life.group(1)), "low": float(life.group(2)), "high": float(life.group(3)),
            "strain_range": max(v for _, v in pts)}


def chart(results, fe, pivot, chord, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4.2))
    rows = fe["rows"]
    th = [0] + [-math.degrees(r["rigid_rotation_arm_root_z"]) for r in rows]
    tq = [0] + [abs(r["servo_torque_Nmm"]) for r in rows]
    lk, t, b_ = case_value("lk"), case_value("t"), case_value("Thickness")
    k = E_MPA * b_ * t ** 3 / 12 / lk
    a.plot(th, tq, "o-", ms=3, label="FE, finite strain (nt = 8)")
    a.plot(th, [k * math.radians(x) for x in th], "--", label="PRBM  K = E b t^3 / (12 l_k)")
    for r in results[1:]:
        a.axvline(-r["turn_deg"], color="0.8", lw=0.8)
        a.annotate("%d" % r["position"], (-r["turn_deg"], 0.3), ha="center")
    a.set_xlabel("spar turn (deg)"), a.set_ylabel("servo torque (N mm)")
    a.set_title("Torque against the PRBM; grey: precision positions")
    a.legend()
    xs = [r["position"] for r in results]
    b.semilogy(xs[1:], [r["miss_target"] / chord * 100 for r in results[1:]], "o-", label="compliant pivot, FE")
    b.semilogy(xs[1:], [max(r["rigid_miss"] / chord * 100, 1e-6) for r in results[1:]], "s--",
               label="rigid pivot at the pole")
    b.semilogy(xs[1:], [r["miss_rigid"] / chord * 100 for r in results[1:]], "^:",
               label="compliant against rigid pivot")
    b.set_xticks(xs[1:]), b.set_xlabel("precision position"), b.set_ylabel("spar miss (% chord)")
    b.set_title("How far the spar misses Table 3")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--out", default=os.path.join(ROOT, "results", "morphing_wing_fe"))
    ap.add_argument("--meshes", default="2,4,8", help="cells through the flexure thickness")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    pivot = single_pivot(args.out)
    chord, lk, t, b = case_value("c"), case_value("lk"), case_value("t"), case_value("Thickness")
    runs = {}
    for nt in [int(v) for v in args.meshes.split(",")]:
        runs[nt] = run_fe(args.out, pivot, nt, args.np)
        print("nt = %d: %d DoFs, %d steps, %d Newton iterations, %.1f s" % (
            nt, runs[nt]["dofs"], runs[nt]["steps"], runs[nt]["newton"], runs[nt]["time"]))
    finest = max(runs)
    results = {nt: evaluate(fe, pivot, chord, lk, t, b) for nt, fe in runs.items()}
    life = fatigue(runs[finest], pivot, args.out)

    lines = ["# The morphing-wing spar on one compliant pivot (issue 13, item 5)", "",
             "Generated by `/usr/bin/python3 postproc/morphing_wing_fe.py` (%d ranks). The synthesis over the paper's "
             "Table 3 finds no four-bar that can do the job; the four spar positions are a near-pure rotation, so "
             "the mechanism is one revolute joint at the pole (%.4f, %.4f) chords, made here as a flexure: "
             "`cases/morphing_wing/compliant_pivot.prm`, chord c = %g mm, flexure l_k = %g mm, t = %g mm, "
             "b = %g mm, root fillets %g t, Semiflex TPU (E = %g MPa), plane stress, finite strain, "
             "driven by a servo torque on the arm's root." % (
                 args.np, pivot[0]["pivot_x"], pivot[0]["pivot_y"], chord, lk, t, b, case_value("rf"), E_MPA), "",
             "## At the precision positions (nt = %d cells through the flexure, %d DoFs)" % (finest, runs[finest]["dofs"]), "",
             "| position | spar turn (deg) | servo torque FE (N mm) | PRBM (N mm) | FE / PRBM | spar miss, compliant (mm) | rigid pivot's miss (mm) | compliant vs rigid pivot (mm) | peak principal strain | peak von Mises (MPa) | strength / von Mises |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results[finest]:
        if r["position"] == 1:
            lines.append("| 1 | 0 (printed pose) | 0 | 0 | - | 0 | 0 | 0 | 0 | 0 | - |")
            continue
        lines.append("| %d | %.3f | %.4f | %.4f | %.3f | %.4f | %.4f | %.4f | %.4f | %.3f | %.1f |" % (
            r["position"], r["turn_deg"], r["torque"], r["prbm"], r["torque"] / r["prbm"], r["miss_target"],
            r["rigid_miss"], r["miss_rigid"], r["strain"], r["mises"], STRENGTH / r["mises"]))
    lines += ["", "## Mesh convergence (position 4)", "",
              "| nt | DoFs | load steps | Newton iterations | run time (s) | servo torque (N mm) | peak principal strain | spar miss (mm) |",
              "|---|---|---|---|---|---|---|---|"]
    for nt, fe in sorted(runs.items()):
        r = results[nt][-1]
        lines.append("| %d | %d | %d | %d | %.1f | %.5f | %.5f | %.4f |" % (
            nt, fe["dofs"], fe["steps"], fe["newton"], fe["time"], r["torque"], r["strain"], r["miss_target"]))
    lines += ["", "## Fatigue, one morphing cycle 1 -> 4 -> 1", "",
              "Peak principal strain in the flexure over the cycle (nt = %d) through `fatigue_life` (printed-TPU "
              "band, elastomer Walker mean correction): strain range %.4f, life nominal %.3g cycles, band %.3g .. %.3g." % (
                  finest, life["strain_range"], life["nominal"], life["low"], life["high"]), "",
              "![torque and position errors](compliant_pivot.png)"]
    md = os.path.join(ROOT, "cases", "morphing_wing", "compliant_pivot.md")
    with open(md, "w") as f:
        f.write("\n".join(lines) + "\n")
    chart(results[finest], runs[finest], pivot, chord, os.path.join(ROOT, "cases", "morphing_wing", "compliant_pivot.png"))
    print("\n".join(lines))


if __name__ == "__main__":
    main()
