#!/usr/bin/python3
"""The model ladder on a case loaded only by a follower pressure (cases/flexure_hinge_large_rotation.prm,
displacement formulation, nt = 2): its linear rungs take the pressure on the undeformed boundary (the
follower's small-deformation limit), so the geometric check sees the ~49 degree rotation and the
climb goes on in finite strain, whose rungs carry the follower pressure itself. Before, the linear
rungs saw no load, found the rotations zero and stopped on 'linear is enough'. The reference is the
same case run directly as a nonlinear static analysis on the mesh of the ladder's last rung: the two
must agree to Newton's tolerance (1e-6 relative here). A plain linear static run of the case takes the
follower pressure the same way: equal to round-off to the run with that pressure as Loads/Pressure."""
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402

CASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "flexure_hinge_large_rotation.prm")
COMMON = ["Finite strain/Formulation=displacement", "Geometry/Parameters/nt=2"]


def run(sets):
    out = tempfile.mkdtemp(prefix="follower-ladder-")
    cmd = ["mpirun", "-np", "2", solver_path(), CASE, "--set", "Output/Directory=" + out, "--set", "Output/Fields=false"]
    for s in COMMON + sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    with open(os.path.join(out, "summary.json")) as f:
        return proc, json.load(f)["quantities"]


def main():
    ladder, q = run(["Analysis=linear static", "Target/Relative error=5", "Target/Quantities=displacement_b_y",
                     "Target/Maximum refinements=1"])
    print(ladder.stdout[-3000:])
    direct, d = run(["Discretization/Global refinements=1"])
    # A plain linear run of the same case takes the follower pressure as Loads/Pressure would.
    linear, l = run(["Analysis=linear static"])
    dead, e = run(["Analysis=linear static", "Finite strain/Follower pressure=", "Loads/Pressure=drive: 0.0095*y"])
    checks = {
        "ladder exits 0 or 4 (target not met)": ladder.returncode in (0, 4),
        "direct run exits 0": direct.returncode == 0,
        "linear rungs take the follower pressure": "linear rungs: Finite strain/Follower pressure" in ladder.stdout,
        "the geometric check asks for finite strain": re.search(r"\(c\) largest rotation (4[5-9]|5\d) deg.*finite strain needed",
                                                               ladder.stdout) is not None,
        "last rung finite strain": q.get("load_steps", 0) > 0,
        "last rung = direct nonlinear run (%.8g, %.8g)" % (q.get("displacement_b_y", 0), d.get("displacement_b_y", 0)):
            abs(q.get("displacement_b_y", 0) / d["displacement_b_y"] - 1) < 1e-6,
        "linear run says it takes the follower pressure": "Loads: Finite strain/Follower pressure" in linear.stdout,
        "linear run = the same pressure given as Loads/Pressure (%.10g, %.10g)" % (
            l.get("displacement_b_y", 0), e.get("displacement_b_y", 0)):
            linear.returncode == 0 and dead.returncode == 0 and
            abs(l.get("displacement_b_y", 0) / e["displacement_b_y"] - 1) < 1e-12,
    }
    for name, ok in checks.items():
        print(("PASS  " if ok else "FAIL  ") + name)
    return 0 if all(checks.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
