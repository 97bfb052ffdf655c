#!/usr/bin/python3
"""A long nonlinear run stopped by SIGTERM or SIGINT (issue 15, item 5): it stops at the next
Newton iteration, keeps its converged load steps and says so. Checked for the solver alone (the
signal to the process: exit 128 + signal) and under mpirun (the signal to mpirun, which passes it
to both ranks): the message names the signal, summary.json's status says interrupted with as many
load steps as curve.csv has rows, every row of curve.csv is whole, nothing temporary is left, and
the fields of the last converged step are written."""
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "postproc"))
from study import mpi_env, solver_path  # noqa: E402
from case_checks import check, finish  # noqa: E402

case = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "cases", "flexure_hinge_large_rotation.prm")


def interrupted_run(name, launcher, sig, expected_code):
    out = tempfile.mkdtemp(prefix="compliant-interrupt-")
    cmd = launcher + [solver_path(), case, "--set", "Output/Directory=" + out,
                      "--set", "Finite strain/Initial step=0.01", "--set", "Finite strain/Maximum step=0.01"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=mpi_env())
    curve = os.path.join(out, "curve.csv")
    start = time.time()
    # Wait for a few converged steps (100 are asked for), then signal.
    while time.time() - start < 120:
        if os.path.exists(curve) and sum(1 for _ in open(curve)) >= 4:
            break
        if proc.poll() is not None:
            break
        time.sleep(0.2)
    proc.send_signal(sig)
    try:
        stdout, stderr = proc.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        proc.kill()
        check(False, "%s: still running 60 s after the signal" % name)
        return
    signal_name = "SIGTERM" if sig == signal.SIGTERM else "SIGINT"
    check(proc.returncode == expected_code if expected_code is not None else proc.returncode != 0,
          "%s: exit code %d" % (name, proc.returncode))
    check("interrupted by " + signal_name in stderr, "%s: says '%s'" % (name, stderr.strip().splitlines()[-1] if stderr.strip() else ""))
    summary = json.load(open(os.path.join(out, "summary.json")))
    rows = list(csv.reader(open(curve)))
    header, data = rows[0], rows[1:]
    check(summary["settings"]["status"].startswith("interrupted by " + signal_name),
          "%s: summary status '%s'" % (name, summary["settings"]["status"]))
    check(int(summary["quantities"]["load_steps"]) == len(data) >= 3 and summary["quantities"]["load_factor"] < 1,
          "%s: %d load steps in the summary, %d rows in curve.csv, load factor %.3g" % (
              name, summary["quantities"]["load_steps"], len(data), summary["quantities"]["load_factor"]))
    check(all(len(r) == len(header) for r in data) and
          abs(float(data[-1][1]) - summary["quantities"]["load_factor"]) < 1e-9,
          "%s: every row whole, the last at the summary's load factor" % name)
    check(os.path.exists(os.path.join(out, "fields.h5")) and
          not [f for f in os.listdir(out) if f.endswith((".tmp", ".partial"))],
          "%s: fields written, nothing temporary left (%s)" % (name, sorted(os.listdir(out))))
    shutil.rmtree(out, ignore_errors=True)


interrupted_run("solver alone, SIGTERM", [], signal.SIGTERM, 128 + signal.SIGTERM)
interrupted_run("solver alone, SIGINT", [], signal.SIGINT, 128 + signal.SIGINT)
interrupted_run("mpirun -np 2, SIGTERM", ["mpirun", "-np", "2"], signal.SIGTERM, None)
finish()
