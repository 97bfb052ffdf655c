#!/usr/bin/python3
"""The matrix-free kernels on SIMD lanes (fast_solver/simd.h) against the same solver built scalar.

Debian's deal.II is configured without vectorization; where the build machine runs AVX2 this
solver instantiates its matrix-free kernels for 4 doubles at once. This benchmark runs the same
cases with this build and with one configured `-DCOMPLIANT_SIMD=OFF` (built into --scalar-build if
it is not there yet, about 15 min on 2 cores), alternately in the same run, and writes
simd_speed.md: whole-process and solve times, their ratios, and the answers of both builds (they
must agree to the solver's tolerance; the sums run in another order).

  /usr/bin/python3 cases/benchmarks/simd_speed.py [--scalar-build DIR] [--repeat N] [--out DIR]
"""
import argparse
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "postproc"))
from report_header import provenance, timed_run  # noqa: E402
from study import mpi_env, solver_path  # noqa: E402

VERIFY = os.path.join(ROOT, "cases", "verification")
# name, case, settings, the answer compared, the solve time's key (the part the kernels serve)
CASES = [
    ("3D cantilever Q2, 140k DoFs (linear, p-multigrid)", os.path.join(HERE, "cantilever.prm"), [],
     "displacement_tip_z", "time_solve"),
    ("2D Lame cylinder Q2, 64 x 128 cells, 66k DoFs (linear, p-multigrid)", os.path.join(VERIFY, "lame_cylinder.prm"),
     ["Discretization/Element degree=2", "Geometry/Parameters/nr=64", "Geometry/Parameters/nc=128"],
     "displacement_inner_x", "time_solve"),
    ("Thin leaf in torsion, Q2, 20 x 40 x 4 cells of 8 : 1 : 1 (linear, p-multigrid, MUMPS below)",
     os.path.join(HERE, "leaf_torsion.prm"), ["Geometry/Parameters/nx=20", "Geometry/Parameters/ny=40",
                                             "Geometry/Parameters/nz=4"], None, "time_solve"),
    ("3D Q1 cantilever 16 x 16 x 48 with error estimates (enriched Q2 solve)",
     os.path.join(VERIFY, "cantilever_3d_end_rotation.prm"),
     ["Discretization/Element degree=1", "Geometry/Parameters/ny=16", "Geometry/Parameters/nz=16",
      "Quantities/Error estimates=true"], "rotational_stiffness_right", "time_error_estimate_solve"),
    ("Finite-strain strip 60 x 12 x 3, Q2, 63.5k DoFs (Newton, matrix-free tangent)",
     os.path.join(HERE, "flexure_finite_strain.prm"),
     ["Geometry/Parameters/nx=60", "Geometry/Parameters/ny=12", "Geometry/Parameters/nz=3"],
     "reaction_moment_left_y", "time_linear_solves"),
]


def build_scalar(directory):
    binary = os.path.join(directory, "solver", "fe", "compliant")
    if os.path.exists(binary):
        return binary
    os.makedirs(directory, exist_ok=True)
    print("building the scalar solver in %s (about 15 min)" % directory, flush=True)
    subprocess.run(["cmake", ROOT, "-DCOMPLIANT_SIMD=OFF"], cwd=directory, check=True, stdout=subprocess.DEVNULL)
    subprocess.run(["make", "-j2", "compliant"], cwd=directory, check=True, stdout=subprocess.DEVNULL)
    return binary


def run(binary, case, sets):
    return timed_run(binary, case, sets, mpi_env())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--scalar-build", default=os.path.join(tempfile.gettempdir(), "compliant-build-scalar"))
    ap.add_argument("--repeat", type=int, default=2, help="runs of each build per case (the fastest counts)")
    ap.add_argument("--out", default=HERE)
    args = ap.parse_args()
    simd, scalar = solver_path(), build_scalar(args.scalar_build)
    rows = ["| case | DoFs | whole process: scalar, SIMD, ratio | solve: scalar, SIMD, ratio | "
            "answer: scalar, SIMD |", "|---|---|---|---|---|"]
    for name, case, sets, answer, solve_key in CASES:
        print("==", name, flush=True)
        best = {}
        for _ in range(args.repeat):
            for label, binary in (("scalar", scalar), ("simd", simd)):
                q = run(binary, case, sets)
                if label not in best or q["wall"] < best[label]["wall"]:
                    best[label] = q
        a, b = best["scalar"], best["simd"]
        key = answer or "strain_energy"
        rows.append("| %s | %d | %.3g s, %.3g s, %.2f | %.3g s, %.3g s, %.2f | %s = %.10g, %.10g |" % (
            name, b["n_dofs"], a["wall"], b["wall"], b["wall"] / a["wall"],
            a[solve_key], b[solve_key], b[solve_key] / a[solve_key], key, a[key], b[key]))
        print(rows[-1], flush=True)
    report = ["# Matrix-free kernels on SIMD lanes against the scalar build", ""] + provenance() + [
              "2 ranks; the faster of %d runs of each build, alternating. *ratio* = SIMD / scalar. Whole "
              "process: the wall time of `mpirun` (start, mesh, solve, error estimates, output). The solve "
              "column is `time_solve` for linear runs, `time_error_estimate_solve` for the error estimates' "
              "enriched solve and `time_linear_solves` for the finite-strain run (all of its CG solves)." %
              args.repeat, ""] + rows + [""]
    path = os.path.join(args.out, "simd_speed.md")
    with open(path, "w") as f:
        f.write("\n".join(report))
    print("wrote", path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
