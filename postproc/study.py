#!/usr/bin/python3
"""Parameter studies: run a case over values of one or more parameters and collect the run
summaries into one CSV table (and optionally a chart).

    postproc/study.py cases/flexure_hinge.prm --vary "Geometry/Parameters/l=2:10:5" \
        --plot l:rotational_stiffness_drive --out results/flexure_study

--vary "Path=v1,v2,v3" or "Path=start:stop:count"; several --vary are combined as a product
(--zip pairs them instead). Extra --set options are passed to every run.
Columns: the varied values, status (ok, or failed: and the solver's message), every quantity, and
for each closed-form comparison the reference (ref:<quantity>~<formula>) and the relative difference
(diff:<quantity>~<formula>).

Each point is written to <out>/points/ as it finishes; a failed point is recorded and the study
goes on (exit code 3 at the end); running the same command again resumes: finished points are read
back, failed and missing ones are run. --jobs N runs N points at once; --point K runs one point (a
scheduler job array: sbatch --array=0-<n-1> ... study.py ... --point $SLURM_ARRAY_TASK_ID, then one
plain run collects the table). The points run in batches of up to --batch (default 50) in one solver
process each (`compliant --points`: the libraries, MPI and PETSc start once per batch, not per point);
--batch 1 runs every point as its own process.
"""
import argparse
import concurrent.futures
import csv
import hashlib
import itertools
import json
import os
import subprocess
import sys
import tempfile
import threading
import time

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


def run_points(case, point_sets, np=2, on_point=None):
    """Runs several points of one case in one solver process (--points: the libraries start once).
    Returns per point ("ok", summary), ("failed", message) or None when the process ended before
    reaching it (then run it alone: run_case gives its own message). on_point(k, result) is called
    as each point ends, while the others run."""
    work = tempfile.mkdtemp(prefix="compliant-points-")
    try:
        points_file = os.path.join(work, "points.txt")
        with open(points_file, "w") as f:
            for k, sets in enumerate(point_sets):
                sets = list(sets)
                if not any(s.startswith("Output/Fields") for s in sets):
                    sets.append("Output/Fields=false")
                f.write("\t".join([os.path.join(work, "p%d" % k)] + sets) + "\n")
        results = [None] * len(point_sets)
        status, seen = os.path.join(work, "points.txt.status"), 0

        def collect():
            nonlocal seen
            if not os.path.exists(status):
                return
            with open(status) as f:
                lines = f.read().split("\n")[:-1]  # complete lines only
            for line in lines[seen:]:
                fields = line.split("\t")
                k = int(fields[0])
                if fields[1] == "ok":
                    with open(os.path.join(work, "p%d" % k, "summary.json")) as f:
                        results[k] = ("ok", json.load(f))
                    subprocess.run(["rm", "-rf", os.path.join(work, "p%d" % k)])
                else:
                    results[k] = ("failed", "error: " + (fields[2] if len(fields) > 2 else "failed"))
                if on_point:
                    on_point(k, results[k])
            seen = len(lines)

        with open(os.path.join(work, "stderr"), "w") as err:
            proc = subprocess.Popen(["mpirun", "-np", str(np), solver_path(), case, "--points", points_file],
                                    stdout=subprocess.DEVNULL, stderr=err, env=mpi_env())
            while proc.poll() is None:
                collect()
                time.sleep(0.05)
        collect()
        if proc.returncode not in (0, 3) and all(r is None for r in results):
            # the batch itself was refused (the case file, an option): every point would be too
            message = open(os.path.join(work, "stderr")).read().strip()[-2000:] or "exit %d" % proc.returncode
            results = [("failed", message)] * len(point_sets)
            for k in range(len(point_sets)) if on_point else []:
                on_point(k, results[k])
        return results
    finally:
        subprocess.run(["rm", "-rf", work])


def run_case_with_curve(case, sets=(), np=2):
    """Runs one nonlinear case; returns (summary, the rows of its curve.csv as dicts)."""
    work = tempfile.mkdtemp(prefix="compliant-curve-")
    try:
        summary = run_case(case, sets, np=np, output_dir=work)
        with open(os.path.join(work, "curve.csv")) as f:
            return summary, list(csv.DictReader(f))
    finally:
        subprocess.run(["rm", "-rf", work])


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
    ap.add_argument("--jobs", type=int, default=1, help="points run at once (each uses --np ranks)")
    ap.add_argument("--batch", type=int, default=50,
                    help="points per solver process (they start the libraries once); 1: a process per point")
    ap.add_argument("--point", type=int, default=None,
                    help="run only point K (0-based, in the order of the table), e.g. a Slurm job array "
                         "task: --point $SLURM_ARRAY_TASK_ID; a later run without --point collects them")
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

    # Every point is written as it finishes (points/<key>.json, atomically), so a study that is
    # interrupted or hits a failing point keeps its finished points, and the same command resumes:
    # finished points are read back, failed ones are run again.
    points_dir = os.path.join(out, "points")
    os.makedirs(points_dir, exist_ok=True)

    def point_sets(combo):
        return args.set + ["%s=%s" % (n, v) for n, v in zip(names, combo)]

    def point_files(index):
        key = hashlib.sha1(json.dumps([os.path.abspath(args.case), point_sets(combos[index])]).encode()).hexdigest()[:16]
        return os.path.join(points_dir, key + ".json"), os.path.join(points_dir, key + ".failed.json")

    def finished(index):
        done, _ = point_files(index)
        if os.path.exists(done):
            with open(done) as f:
                return dict(json.load(f), resumed=True)
        return None

    def save(index, record):
        done, failed = point_files(index)
        target = done if record["status"] == "ok" else failed
        with open(target + ".partial", "w") as f:
            json.dump(record, f)
        os.replace(target + ".partial", target)
        if record["status"] == "ok" and os.path.exists(failed):
            os.remove(failed)
        return record

    def run_point(index):
        record = finished(index)
        if record is not None:
            return record
        sets = point_sets(combos[index])
        try:
            record = {"sets": sets, "status": "ok", "summary": run_case(args.case, sets, args.np)}
        except RuntimeError as e:
            record = {"sets": sets, "status": "failed", "message": str(e)}
        return save(index, record)

    def run_batch(indices, report):
        """Points in one solver process, each saved and reported as it ends; those the process did
        not reach run alone."""
        def on_point(k, result):
            i, sets = indices[k], point_sets(combos[indices[k]])
            if result[0] == "ok":
                report(i, save(i, {"sets": sets, "status": "ok", "summary": result[1]}))
            else:
                report(i, save(i, {"sets": sets, "status": "failed", "message": result[1]}))
        results = run_points(args.case, [point_sets(combos[i]) for i in indices], args.np, on_point)
        for i, result in zip(indices, results):
            if result is None:
                report(i, run_point(i))

    def reason(message):
        """The solver's own message (its 'error:' line), not mpirun's closing banner."""
        lines = [l.strip() for l in message.strip().splitlines() if l.strip() and not l.startswith("---")]
        errors = [l for l in lines if l.startswith("error:")]
        return (errors or lines or ["unknown failure"])[0]

    def label(combo):
        return "  ".join("%s=%s" % (n.split("/")[-1], v) for n, v in zip(names, combo))

    if args.point is not None:  # one point of a scheduler job array
        if not 0 <= args.point < len(combos):
            sys.exit("error: --point %d: the study has points 0 to %d" % (args.point, len(combos) - 1))
        record = run_point(args.point)
        print(label(combos[args.point]), record["status"])
        sys.exit(0 if record["status"] == "ok" else 3)

    records = [None] * len(combos)
    table = os.path.join(out, "study.csv")

    def write_table():
        rows = []
        for combo, record in zip(combos, records):
            if record is None:
                continue
            row = {n.split("/")[-1]: v for n, v in zip(names, combo)}
            if record["status"] == "ok":
                row["status"] = "ok"
                row.update(flatten(record["summary"]))
            else:
                row["status"] = "failed: " + reason(record["message"])[:300]
            rows.append(row)
        if not rows:
            return rows
        columns = list(rows[0].keys())
        for r in rows[1:]:
            columns += [k for k in r if k not in columns]
        with open(table + ".partial", "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=columns)
            w.writeheader()
            w.writerows(rows)
        os.replace(table + ".partial", table)
        return rows

    def report(i, record):
        records[i] = record
        status = record["status"] + (" (resumed)" if record.get("resumed") else "")
        if record["status"] != "ok":
            status += ": " + reason(record["message"])[:200]
        print(label(combos[i]), status, flush=True)

    for i in range(len(combos)):
        if finished(i) is not None:
            report(i, finished(i))
    pending = [i for i in range(len(combos)) if records[i] is None]
    write_table()
    # Batches: every job gets its share, at most --batch points per solver process.
    jobs = max(1, args.jobs)
    size = max(1, min(args.batch, -(-len(pending) // jobs)))
    batches = [pending[k:k + size] for k in range(0, len(pending), size)]
    lock = threading.Lock()

    def report_and_write(i, record):
        with lock:
            report(i, record)
            write_table()

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        if size == 1:
            futures = [pool.submit(lambda i: report_and_write(i, run_point(i)), b[0]) for b in batches]
        else:
            futures = [pool.submit(run_batch, b, report_and_write) for b in batches]
        for future in concurrent.futures.as_completed(futures):
            future.result()
    rows = [r for r in write_table() if r["status"] == "ok"]
    print("table:", table)
    failures = [label(c) for c, r in zip(combos, records) if r["status"] != "ok"]
    if failures:
        print("error: %d of %d points failed (recorded in the table; rerun the same command to retry "
              "them): %s" % (len(failures), len(combos), "; ".join(failures)), file=sys.stderr)
    if not rows:
        sys.exit(3)
    for spec in args.plot:
        from chart import plot_study  # local module, imported only when a chart is asked for
        print("chart:", plot_study(table, spec, out))
    for spec in args.accuracy:
        print("chart:", accuracy_chart(rows, spec, args.target, out))
    if failures:
        sys.exit(3)


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
