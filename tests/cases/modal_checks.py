#!/usr/bin/python3
"""Modal analysis checks that need more than one run or read the written fields.

    modal_checks.py ranks    CASE   1 and 2 MPI ranks give the same frequencies and effective masses
                                    (rigid-body modes: both near zero; repeated modes: frequency only)
    modal_checks.py shape    CASE   the first flexible mode of the free-free beam (mode 7) has its
                                    nodes where Euler-Bernoulli puts them, x/L = 0.2242, 0.7758
    modal_checks.py errors   CASE   a bad Modal/Shift, pin, edge support or mirror tie is refused with
                                    exit code 2 and a message
"""
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, run_case, solver_path  # noqa: E402


def ranks(case):
    one, two = run_case(case, np=1)["quantities"], run_case(case, np=2)["quantities"]
    f = {int(k.split("_")[1]): v for k, v in one.items() if k.startswith("frequency_")}
    # Rigid-body modes (below 1e-3 of the highest mode computed) are round-off, and modes of a
    # repeated frequency are any basis of their space: only their frequencies are compared.
    rigid = {n for n, v in f.items() if abs(v) < 1e-3 * max(f.values())}
    repeated = rigid | {n for n in f for m in f if m != n and n not in rigid and
                        abs(f[n] - f[m]) <= 1e-6 * abs(f[n])}
    bad = 0
    for key in sorted(one):
        if key.startswith("frequency_"):
            # Round-off in K is of the order eps lambda_max; against lambda_1 that is
            # eps lambda_max / lambda_1 ~ 2e-16 * 1e10 = 2e-6 for this slender beam.
            n = int(key.split("_")[1])
            ok = (n in rigid and abs(two[key]) < 1e-3 * max(f.values())) or \
                abs(one[key] - two[key]) <= 1e-6 * abs(one[key])
        elif key.startswith("effective_mass_fraction_"):
            if not key.endswith("_sum") and int(key.rsplit("_", 1)[1]) in repeated:
                continue
            ok = abs(one[key] - two[key]) <= 1e-8  # fractions of the total mass
        else:
            continue
        print("%-5s %-36s 1 rank %.12g   2 ranks %.12g" % ("ok" if ok else "DIFF", key, one[key], two[key]))
        bad += not ok
    return bad


def shape(case):
    import h5py
    import numpy as np
    out = tempfile.mkdtemp(prefix="compliant-modal-")
    summary = run_case(case, ["Output/Fields=true"], np=2, output_dir=out)
    L = summary["parameters"]["L"]
    with h5py.File(os.path.join(out, "fields.h5")) as f:
        x, mode = f["nodes"][:, 0], f["mode_7"][:]
    subprocess.run(["rm", "-rf", out])
    peak = np.max(np.linalg.norm(mode, axis=1))
    # Centre-line average of u_y per x station, then the zero crossings.
    stations = np.unique(np.round(x, 9))
    uy = np.array([mode[np.abs(x - s) < 1e-9, 1].mean() for s in stations])
    crossings = [stations[i] - uy[i] * (stations[i + 1] - stations[i]) / (uy[i + 1] - uy[i])
                 for i in range(len(uy) - 1) if uy[i] * uy[i + 1] < 0]
    # Free-free Euler-Bernoulli mode 1: cos x cosh x = 1 at beta L = 4.73004, nodes at
    # x/L = 0.22416 and 0.77584 (Blevins, table 8-1).
    expected = [0.22416, 0.77584]
    print("largest displacement of the written mode: %.12g (expected 1)" % peak)
    print("nodes of mode 7 at x/L =", [c / L for c in crossings], "expected", expected)
    bad = abs(peak - 1) > 1e-6  # the HDF5 file holds single precision
    bad += len(crossings) != 2 or any(abs(c / L - e) > 0.002 for c, e in zip(crossings, expected))
    return bad


def errors(case):
    bad = 0
    for setting, message in [("Modal/Shift=fast", "Modal/Shift"),
                             ("Extra constraints/Pins=B: nowhere, left", "unknown boundary"),
                             ("Extra constraints/Edge supports=left: z", "joined by '&'"),
                             ("Extra constraints/Mirror ties=nowhere: plane=y 0, odd=y",
                              "unknown boundary"),
                             ("Extra constraints/Mirror ties=right: plane=y H/4, odd=y",
                              "has no mirror node"),
                             ("Extra constraints/Mirror ties=right: odd=y", "names no mirror plane"),
                             ("Extra constraints/Mirror ties=right: plane=y 0, odd=y, even=y",
                              "both even and odd")]:
        cmd = ["mpirun", "-np", "1", solver_path(), case, "--set", setting, "--check"]
        proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
        ok = proc.returncode == 2 and message in proc.stderr
        print("%-5s --set \"%s\": exit %d, %s" % ("ok" if ok else "FAIL", setting, proc.returncode,
                                                  proc.stderr.strip()[:300]))
        bad += not ok
    return bad


if __name__ == "__main__":
    check, case = sys.argv[1], sys.argv[2]
    sys.exit(1 if {"ranks": ranks, "shape": shape, "errors": errors}[check](case) else 0)
