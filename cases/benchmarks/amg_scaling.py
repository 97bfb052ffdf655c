#!/usr/bin/python3
"""AMG scaling benchmark: CG + GAMG (rigid-body near null space) iterations and times as a
cantilever mesh is refined (each level ~4x DoFs in 2D, ~8x in 3D), with the MUMPS direct
solver on the same meshes as the in-run peer.

    /usr/bin/python3 cases/benchmarks/amg_scaling.py [2d|3d|500k] [--np 2]
"""
import argparse
import os
import sys

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(root, "postproc"))
from study import run_case  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("model", choices=["2d", "3d", "500k"])
ap.add_argument("--np", type=int, default=2)
ap.add_argument("--no-direct", action="store_true", help="skip the MUMPS peer")
args = ap.parse_args()

verification = os.path.join(root, "cases", "verification")
if args.model == "2d":
    case, meshes = os.path.join(verification, "cantilever_2d.prm"), [{"ny": n} for n in (4, 8, 16, 32, 64)]
elif args.model == "3d":
    case, meshes = os.path.join(verification, "cantilever_3d.prm"), [{"ny": n, "nz": n} for n in (2, 4, 8)]
else:
    case, meshes = os.path.join(verification, "cantilever_3d.prm"), [{"ny": 12, "nz": 12, "nx": 140}]

print("%-22s %10s %6s %9s %9s %12s %9s %8s" % ("mesh", "DoFs", "its", "AMG s", "MUMPS s", "tip defl.", "MUMPS/AMG", "ranks"))
for mesh in meshes:
    sets = ["Geometry/Parameters/%s=%d" % kv for kv in mesh.items()]
    amg = run_case(case, sets + ["Linear solver/Method=cg-amg"], np=args.np)["quantities"]
    direct_time = float("nan")
    if not args.no_direct:
        direct = run_case(case, sets + ["Linear solver/Method=direct"], np=args.np)["quantities"]
        direct_time = direct["time_solve"]
    print("%-22s %10d %6d %9.2f %9.2f %12.6e %9.2f %8d" % (
        ",".join("%s=%d" % kv for kv in mesh.items()), amg["n_dofs"], amg["solver_iterations"],
        amg["time_solve"], direct_time, amg["mean_displacement_right_y"], direct_time / amg["time_solve"],
        amg["n_ranks"]), flush=True)
