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
    # Integers stay integers: integer entries (Element degree, Global refinements) refuse "1.0".
    return [(int(v) if v.strip().lstrip("-").isdigit() else float(v)) if _is_number(v) else v
            for v in text.split(",")]


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
    ap.add_argument("--accuracy", action="append", default=[],
                    help="QOI[=REFERENCE][:FAMILY]: error of QOI against wall time (time_total), log-log, one "
                         "line per value of the varied FAMILY column (e.g. 'Element degree'); the reference "
                         "is the given value, else the closed form of QOI's comparison, else the study's "
                         "most expensive run (then the error is an estimate and the chart says so)")
    ap.add_argument("--target", type=float, default=None, help="percent, drawn on --accuracy charts")
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
    for spec in args.accuracy:
        print("chart:", accuracy_chart(rows, spec, args.target, out))


def accuracy_chart(rows, spec, target, out):
    """Relative error of a quantity against wall time for every run of a study."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    family = None
    if ":" in spec:
        spec, family = spec.split(":", 1)
    qoi, reference, label = spec, None, "given reference"
    if "=" in spec:
        qoi, value = spec.split("=", 1)
        reference = float(value)
    if reference is None:
        refs = [r[k] for r in rows for k in r if k.startswith("ref:%s~" % qoi)]
        if refs:
            reference, label = float(refs[0]), "closed form"
    if reference is None:
        finest = max(rows, key=lambda r: float(r.get("time_total", 0)))
        reference, label = float(finest[qoi]), "most expensive run (estimate)"
    groups = {}
    for r in rows:
        if qoi not in r or "time_total" not in r:
            continue
        key = r.get(family.split("/")[-1], "") if family else ""
        err = abs(float(r[qoi]) - reference) / abs(reference)
        groups.setdefault(key, []).append((float(r.get("n_dofs", 0)), float(r["time_total"]), err))
    fig, ax = plt.subplots(figsize=(7, 5))
    for key, pts in sorted(groups.items()):
        pts = sorted(p for p in pts if p[2] > 0)  # joined in order of DoFs, as the mesh is refined
        if pts:
            ax.loglog([p[1] for p in pts], [100 * p[2] for p in pts], "o-",
                      label=("%s = %s" % (family.split("/")[-1], key)) if family else qoi)
    if target:
        ax.axhline(target, color="r", lw=1, label="target %.2g %%" % target)
    ax.set_xlabel("wall time of the run (time_total, s)")
    ax.set_ylabel("relative error of %s (%%), against the %s" % (qoi, label))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    path = os.path.join(out, "accuracy_%s.png" % qoi)
    fig.savefig(path, dpi=110)
    return path


if __name__ == "__main__":
    main()
