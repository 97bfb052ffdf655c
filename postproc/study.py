#!/usr/bin/python3
"""Parameter studies: run a case over values of one or more parameters and collect the run
summaries into one CSV table (and optionally a chart).

    postproc/study.py cases/flexure_hinge.prm --vary "Geometry/Parameters/l=2:10:5" \
        --plot l:rotational_stiffness_drive --out results/flexure_study

--vary "Path=v1,v2,v3" or "Path=start:stop:count"; several --vary are combined as a product
(--zip pairs them instead). Extra --set options are passed to every run.
Columns: the varied values, every quantity, and for each closed-form comparison the reference
(ref:<quantity>~<formula>) and the relative difference (diff:<quantity>~<formula>).
"""
import argparse
import csv
import itertools
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def solver_path():
    return os.environ.get("COMPLIANT_SOLVER", os.path.join(ROOT, "build", "solver", "fe", "compliant"))


def mpi_env():
    env = dict(os.environ)
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    return env


def run_case(case, sets=(), np=2, output_dir=None, quiet=True):
    """Runs one case and returns its summary (dict). Raises RuntimeError with the solver's message."""
    own_dir = output_dir is None
    output_dir = output_dir or tempfile.mkdtemp(prefix="compliant-run-")
    cmd = ["mpirun", "-np", str(np), solver_path(), case, "--set", "Output/Directory=" + output_dir]
    if not any(s.startswith("Output/Fields") for s in sets):
        cmd += ["--set", "Output/Fields=false"]
    for s in sets:
        cmd += ["--set", s]
    proc = subprocess.run(cmd, capture_output=True, text=True, env=mpi_env())
    if not quiet:
        print(proc.stdout)
    if proc.returncode != 0:
        raise RuntimeError("run failed (exit %d): %s\n%s" % (proc.returncode, " ".join(cmd),
                                                            proc.stderr.strip()[-2000:]))
    with open(os.path.join(output_dir, "summary.json")) as f:
        summary = json.load(f)
    if own_dir:
        subprocess.run(["rm", "-rf", output_dir])
    return summary


def flatten(summary):
    row = dict(summary["quantities"])
    for c in summary["comparisons"]:
        key = c["quantity"] + "~" + c["closed_form"]
        row["ref:" + key] = c["reference"]
        row["diff:" + key] = c["relative_difference"]
    return row


def parse_values(text):
    if text.count(":") == 2:
        start, stop, count = text.split(":")
        start, stop, count = float(start), float(stop), int(count)
        return [start + (stop - start) * i / (count - 1) for i in range(count)] if count > 1 else [start]
    return [float(v) if _is_number(v) else v for v in text.split(",")]


def _is_number(v):
    try:
        float(v)
        return True
    except ValueError:
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("case")
    ap.add_argument("--vary", action="append", required=True, help='"Section/Name=values"')
    ap.add_argument("--zip", action="store_true", help="pair the --vary lists instead of a product")
    ap.add_argument("--set", action="append", default=[], help="fixed override for every run")
    ap.add_argument("--np", type=int, default=2)
    ap.add_argument("--out", default=None, help="output folder (default results/study_<case>)")
    ap.add_argument("--plot", action="append", default=[],
                    help="x:y chart from the table columns (reference curves are added when y has comparisons)")
    args = ap.parse_args()

    names, lists = [], []
    for v in args.vary:
        if "=" not in v:
            sys.exit("error: --vary \"%s\": expected \"Section/Name=values\"" % v)
        name, values = v.split("=", 1)
        names.append(name.strip())
        lists.append(parse_values(values))
    combos = list(zip(*lists)) if args.zip else list(itertools.product(*lists))
    out = args.out or os.path.join("results", "study_" + os.path.splitext(os.path.basename(args.case))[0])
    os.makedirs(out, exist_ok=True)

    rows = []
    for combo in combos:
        sets = args.set + ["%s=%s" % (n, v) for n, v in zip(names, combo)]
        try:
            summary = run_case(args.case, sets, args.np)
        except RuntimeError as e:
            sys.exit("error: " + str(e))
        row = {n.split("/")[-1]: v for n, v in zip(names, combo)}
        row.update(flatten(summary))
        rows.append(row)
        print("  ".join("%s=%s" % (n.split("/")[-1], v) for n, v in zip(names, combo)), "done", flush=True)

    columns = list(rows[0].keys())
    for r in rows[1:]:
        columns += [k for k in r if k not in columns]
    table = os.path.join(out, "study.csv")
    with open(table + ".partial", "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    os.replace(table + ".partial", table)
    print("table:", table)
    for spec in args.plot:
        from chart import plot_study  # local module, imported only when a chart is asked for
        print("chart:", plot_study(table, spec, out))


if __name__ == "__main__":
    main()
