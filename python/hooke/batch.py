"""hooke.batch: studies of many independent jobs (calibrate and certify, or identify) on Dask distributed.

A study is a table of jobs, one per row (docs/batch.md):

    name, mesh, young, poisson, method, density, strain, loads, law, plane, thickness, objective, params

`run(jobs, out_dir, client=None)` runs every job as one task on a Dask cluster (a LocalCluster of single-threaded
worker processes by default, or any cluster given as a Client or a scheduler address) and writes each result as it
completes to `out_dir`/results.csv, and each model to `out_dir`/models/. The study is resumable: a job is keyed by a
hash of its inputs (the mesh file's bytes included) and a rerun skips the jobs whose results are in the table. A job
that fails with an error (a malformed mesh, a solver that does not converge) is recorded as failed with its message
and not retried; a worker that dies mid-task has its task rerun elsewhere by Dask (up to the scheduler's
`distributed.scheduler.allowed-failures`, then the job is recorded as failed with KilledWorker). No scheduler code
lives here: the scheduling, the retries and the worker restarts are Dask's.

`python3 -m hooke.batch STUDY.csv -o DIR [--scheduler ADDRESS] [--workers N]` (and `hooke batch`) is the same.
"""
import csv
import hashlib
import io
import json
import os
import pathlib
import sys
import time

#: The batch's own columns: (name, type, default). `mesh`, `young` and `poisson` are required. `law` (a declared
#: setting) is also the FEM law of the references of identify jobs; `strain` is the certificate's (and identify's).
_OWN_COLUMNS = (
    ("name", str, ""),
    ("mesh", str, None),
    ("young", float, None),
    ("poisson", float, None),
    ("strain", float, 0.01),
    ("loads", str, "stretch;compress;shear"),
    ("plane", str, "stress"),
    ("thickness", float, None),
    ("objective", str, "positions"),
    ("params", str, "auto"),
)
_KINDS = {"number": float, "integer": int, "flag": bool, "choice": str, "text": str}


def _declared_columns():
    """The calibration settings declared for the batch (hooke.settings("batch"): method, density, the term law, the
    surface and tet options, law, strain_range, ...): (keyword, type, default), one column each."""
    from . import _hooke

    out = []
    for d in _hooke._settings("batch"):
        kind = _KINDS[d["type"]]
        default = d["default"]
        if kind is bool:
            default = default == "on"
        elif kind in (int, float):
            default = kind(default) if default != "" else None
        out.append((d["keyword"], kind, default))
    return tuple(out)


#: The study table's columns: (name, type, default), the batch's own and every declared calibration setting.
STUDY_COLUMNS = _OWN_COLUMNS[:4] + _declared_columns() + _OWN_COLUMNS[4:]
#: The columns handed to hooke.calibrate as keywords.
CALIBRATION_COLUMNS = tuple(c for c, _, _ in _declared_columns())

#: The results table's columns, in order.
RESULT_COLUMNS = (
    "key", "name", "mesh", "young", "poisson", "method", "strain", "loads", "status", "error", "method_used",
    "relative_l2_stretch", "relative_l2_compress", "relative_l2_shear", "worst_relative_l2", "held_out_rms", "model",
    "seconds", "peak_memory_mb", "worker",
)

RESULTS_FILE = "results.csv"
MODELS_DIR = "models"


class StudyError(ValueError):
    """A malformed study table: names the file, the line and the column."""


# ---------------------------------------------------------------------------------------------------------------------
# The study table


def _value(text, kind, default, where, column):
    text = "" if text is None else str(text).strip()
    if text == "" or text.lower() == "nan":
        if default is None and column in ("mesh", "young", "poisson"):
            raise StudyError(f"{where}: column '{column}' is empty; it is required")
        return default
    if kind is float:
        try:
            v = float(text)
        except ValueError:
            raise StudyError(f"{where}: column '{column}' is '{text}', not a number") from None
        if v != v or v in (float("inf"), float("-inf")):
            raise StudyError(f"{where}: column '{column}' is '{text}', not a finite number")
        return v
    if kind is int:
        try:
            return int(text)
        except ValueError:
            raise StudyError(f"{where}: column '{column}' is '{text}', not an integer") from None
    if kind is bool:
        if text.lower() not in ("on", "off", "true", "false", "1", "0"):
            raise StudyError(f"{where}: column '{column}' is '{text}', not on or off")
        return text.lower() in ("on", "true", "1")
    return text


def normalise_job(row, base_dir=".", where="job"):
    """One job as a dict of every study column, typed, with defaults filled in and the mesh path made absolute
    (relative paths are relative to `base_dir`, the study table's folder). Raises StudyError naming `where` and the
    column for an unknown column, a missing required one or a value that is not a number where one is needed."""
    known = {c for c, _, _ in STUDY_COLUMNS}
    unknown = sorted(k for k in row if k not in known and k is not None and str(k).strip() != "")
    if unknown:
        raise StudyError(f"{where}: unknown column(s) {', '.join(unknown)} (known: {', '.join(sorted(known))})")
    job = {c: _value(row.get(c), kind, default, where, c) for c, kind, default in STUDY_COLUMNS}
    mesh = pathlib.Path(job["mesh"])
    job["mesh"] = str(mesh if mesh.is_absolute() else (pathlib.Path(base_dir) / mesh).resolve())
    if not job["name"]:
        job["name"] = f"{pathlib.Path(job['mesh']).stem}-{job['method']}-nu{job['poisson']:g}"
    return job


def read_study(path):
    """The jobs of the study table at `path` (CSV with a header row; see STUDY_COLUMNS), normalised. Raises
    StudyError naming the file and line of a malformed row."""
    path = pathlib.Path(path)
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        if reader.fieldnames is None:
            raise StudyError(f"{path}: empty study table (expected a header row with mesh, young, poisson, ...)")
        return [normalise_job(row, path.parent, f"{path}:{reader.line_num}") for row in reader]


def job_key(job):
    """A hash of everything that determines a job's result: its columns (but its name) and the bytes of its mesh file,
    and hooke's version. Two jobs with the same key give the same result."""
    import hooke

    h = hashlib.sha256()
    inputs = {k: v for k, v in job.items() if k not in ("name", "key")}
    inputs["mesh"] = pathlib.Path(job["mesh"]).name
    h.update(json.dumps(inputs, sort_keys=True).encode())
    h.update(hooke.__version__.encode())
    try:
        with open(job["mesh"], "rb") as f:
            for block in iter(lambda: f.read(1 << 20), b""):
                h.update(block)
    except OSError as e:
        h.update(f"unreadable: {e.strerror}".encode())
    return h.hexdigest()[:20]


def _jobs_from(jobs, base_dir="."):
    if isinstance(jobs, (str, os.PathLike)):
        return read_study(jobs)
    if hasattr(jobs, "to_dict"):  # a pandas DataFrame
        jobs = jobs.to_dict("records")
    out = []
    for i, row in enumerate(jobs):
        out.append(normalise_job(dict(row), base_dir, f"job {i}"))
    return out


# ---------------------------------------------------------------------------------------------------------------------
# One job, in a worker


def _reset_peak_memory():
    # Linux: writing 5 to clear_refs resets the process's peak resident set (VmHWM), so the peak is this job's.
    try:
        with open("/proc/self/clear_refs", "w") as f:
            f.write("5")
        return True
    except OSError:
        return False


def _peak_memory_mb():
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    import resource

    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


_MALLOC_TUNED = False


def _tune_malloc():
    """Undoes, once per worker process, what Dask's nanny does to glibc's malloc: its default environment sets
    MALLOC_TRIM_THRESHOLD_=65536 (to hand memory back to the system early), which also freezes the mmap threshold at
    128 KiB, so that every vector of a solve above that size is a fresh mmap and page faults: the nu-range tasks ran
    1.5x slower in a worker than in a plain process (8.6 s against 5.9 s for one task). A 128 MiB trim threshold and
    a 32 MiB mmap threshold (glibc's largest) give back the plain process's speed or better (4.4-4.9 s)."""
    global _MALLOC_TUNED
    if _MALLOC_TUNED:
        return
    _MALLOC_TUNED = True
    try:
        import ctypes

        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(-1, 128 << 20)  # M_TRIM_THRESHOLD
        libc.mallopt(-3, 32 << 20)  # M_MMAP_THRESHOLD
    except (OSError, AttributeError):  # not glibc: nothing to undo
        pass


def _error_text(e):
    return f"{type(e).__name__}: {e}"


def run_job(job, out_dir):
    """Runs one job where it is called (a Dask worker, or here): reads the mesh, calibrates (or identifies, for
    method 'identify'), certifies against the linear FEM on the job's loads at its strain and writes the model to
    `out_dir`/models/<name>-<key>.json (atomically). Returns the result as a dict of RESULT_COLUMNS. Every error is
    caught and returned as a failed result with its message: a hooke error is a property of the job, and rerunning
    it would fail the same way."""
    import socket
    import warnings

    import hooke

    _tune_malloc()
    start = time.perf_counter()
    _reset_peak_memory()
    result = {c: "" for c in RESULT_COLUMNS}
    result.update({k: job[k] for k in ("key", "name", "mesh", "young", "poisson", "method", "strain", "loads")})
    result["worker"] = f"{socket.gethostname()}:{os.getpid()}"
    try:
        mesh = hooke.read_mesh(job["mesh"])
        material = hooke.Material(job["young"], job["poisson"], thickness=job["thickness"], law=job["law"],
                                  plane=job["plane"])
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", hooke.ValidityWarning)
            if job["method"] == "identify":
                model, report = hooke.identify(mesh, material, params=job["params"], objective=job["objective"],
                                               strain=job["strain"], density=job["density"])
                result["held_out_rms"] = report.get("held_out_relative_l2_rms", "")
            else:
                options = {c: job[c] for c in CALIBRATION_COLUMNS}
                if not job["strain_range"]:
                    del options["law"]  # then only the material's: the FEM law of method fem
                model = hooke.calibrate(mesh, material, **options)
        result["method_used"] = model.method
        loads = [name.strip() for name in job["loads"].replace(",", ";").split(";") if name.strip()]
        cases = hooke.certify(model, job["strain"], loads=loads)
        for case in cases:
            result["relative_l2_" + case["load"]] = case["relative_l2"]
        result["worst_relative_l2"] = max(case["relative_l2"] for case in cases)
        models = pathlib.Path(out_dir) / MODELS_DIR
        models.mkdir(parents=True, exist_ok=True)
        path = models / f"{_safe(job['name'])}-{job['key']}.json"
        hooke.write_model(str(path), model)
        result["model"] = str(path.relative_to(out_dir))
        result["status"] = "ok"
    except Exception as e:  # recorded, never raised: see the docstring
        result["status"] = "failed"
        result["error"] = _error_text(e)
    result["seconds"] = round(time.perf_counter() - start, 4)
    result["peak_memory_mb"] = round(_peak_memory_mb(), 1)
    return result


def _safe(name):
    return "".join(c if c.isalnum() or c in "-_.+" else "_" for c in name)[:80]


# ---------------------------------------------------------------------------------------------------------------------
# The results table


class ResultsTable:
    """`out_dir`/results.csv, written by the driver alone: one line per result, appended with one write and synced,
    so a run killed at any instant leaves every finished result whole (a torn last line is dropped when the table is
    next opened)."""

    def __init__(self, path):
        self.path = pathlib.Path(path)
        self._keys = set()
        self._rows = []
        if self.path.exists():
            text = self.path.read_text()
            whole = text[: text.rfind("\n") + 1]
            if whole != text:  # a torn last line from a killed run
                with open(self.path, "r+") as f:
                    f.truncate(len(whole.encode()))
            if whole:
                for row in csv.DictReader(io.StringIO(whole)):
                    self._keys.add(row["key"])
                    self._rows.append(row)

    def keys(self):
        return set(self._keys)

    def rows(self):
        return list(self._rows)

    def append(self, result):
        """Writes `result` unless a result with its key is there; returns whether it wrote."""
        if result["key"] in self._keys:
            return False
        buffer = io.StringIO()
        writer = csv.DictWriter(buffer, fieldnames=RESULT_COLUMNS, lineterminator="\n")
        new = not self.path.exists() or self.path.stat().st_size == 0
        if new:
            writer.writeheader()
        writer.writerow({c: result.get(c, "") for c in RESULT_COLUMNS})
        fd = os.open(self.path, os.O_WRONLY | os.O_APPEND | os.O_CREAT, 0o644)
        try:
            os.write(fd, buffer.getvalue().encode())
            os.fsync(fd)
        finally:
            os.close(fd)
        self._keys.add(result["key"])
        self._rows.append({c: str(result.get(c, "")) for c in RESULT_COLUMNS})
        return True


def read_results(out_dir):
    """The results table of a study folder as a pandas DataFrame."""
    import pandas

    return pandas.read_csv(pathlib.Path(out_dir) / RESULTS_FILE)


# ---------------------------------------------------------------------------------------------------------------------
# The cluster


def local_cluster(workers=None):
    """A Dask LocalCluster of `workers` single-threaded worker processes (default: one per core), each with
    cores / workers OpenMP threads so that the workers do not oversubscribe the cores."""
    from dask.distributed import LocalCluster
    import logging

    cores = os.cpu_count() or 1
    n = int(workers) if workers else cores
    if n < 1:
        raise ValueError("local_cluster: workers must be >= 1")
    threads = str(max(1, cores // n))
    return LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=None,
                        silence_logs=logging.ERROR,
                        env={"OMP_NUM_THREADS": threads, "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"})


def connect(client=None, workers=None):
    """A dask.distributed.Client: `client` itself, a new Client to the scheduler address `client`
    ("tcp://host:8786"), or, for None or "local", a Client of local_cluster(workers). Returns (client, close): call
    close() when done (it closes only what this function started)."""
    from dask.distributed import Client

    if client is None or client == "local":
        cluster = local_cluster(workers)
        c = Client(cluster)

        def close():
            c.close()
            cluster.close()

        return c, close
    if isinstance(client, str):
        c = Client(client)
        return c, c.close
    return client, (lambda: None)


class _Progress:
    def __init__(self, total, skipped, enabled):
        self.total, self.skipped, self.enabled = total, skipped, enabled
        self.done = self.failed = 0
        self.last = 0.0

    def show(self, running, final=False):
        if not self.enabled:
            return
        now = time.monotonic()
        if not final and now - self.last < 0.2:
            return
        self.last = now
        width = 30
        finished = self.done + self.failed
        bar = "#" * (width * finished // max(1, self.total))
        line = (f"\rbatch [{bar:<{width}}] {finished}/{self.total}: {self.done} done, {self.failed} failed, "
                f"{running} running" + (f" ({self.skipped} already in the table)" if self.skipped else ""))
        sys.stderr.write(line + ("\n" if final else ""))
        sys.stderr.flush()


def _running(client):
    # Tasks assigned to workers, at most one per worker thread (the scheduler queues more on a worker than it runs).
    try:
        assigned = sum(len(v) for v in client.processing().values())
        return min(assigned, sum(client.nthreads().values()))
    except Exception:
        return "?"


def run(jobs, out_dir, client=None, workers=None, progress=True, retry_failed=False):
    """Runs the study `jobs` (a study table's path, a list of dicts or a pandas DataFrame with STUDY_COLUMNS) on Dask
    and returns the results table (pandas DataFrame of RESULT_COLUMNS, one row per job of the study).

    out_dir       the study folder: results.csv and models/ (created)
    client        None or "local": a LocalCluster of `workers` processes (default one per core), closed at the end;
                  a scheduler address ("tcp://host:8786"); or a dask.distributed.Client
    retry_failed  run again the jobs recorded as failed (their rows are replaced)

    A rerun runs only the jobs whose key is not in the table. Raises StudyError for a malformed study table."""
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    base = pathlib.Path(jobs).parent if isinstance(jobs, (str, os.PathLike)) else "."
    study = _jobs_from(jobs, base)
    for job in study:
        job["key"] = job_key(job)
    if retry_failed:
        _drop_failed(out / RESULTS_FILE)
    table = ResultsTable(out / RESULTS_FILE)
    present = table.keys()
    todo, seen = [], set()
    for job in study:
        if job["key"] not in present and job["key"] not in seen:
            todo.append(job)
            seen.add(job["key"])
    bar = _Progress(len(todo), len(study) - len(todo), progress)
    if todo:
        dask_client, close = connect(client, workers)
        try:
            futures = {dask_client.submit(run_job, job, str(out), key="hooke-job-" + job["key"], pure=False): job
                       for job in todo}

            def record(future):
                job = futures[future]
                if future.status == "finished":
                    result = future.result()
                else:  # the task itself died (KilledWorker after the allowed failures), or was cancelled
                    result = {c: "" for c in RESULT_COLUMNS}
                    result.update({k: job[k] for k in ("key", "name", "mesh", "young", "poisson", "method", "strain",
                                                       "loads")})
                    result["status"] = "failed"
                    try:
                        result["error"] = _error_text(future.exception())
                    except Exception as e:
                        result["error"] = _error_text(e)
                table.append(result)
                return result["status"] == "ok"

            _collect(dask_client, futures, bar, record)
        finally:
            close()
    bar.show(0, final=True)
    return _study_results(table, study)


def _collect(client, futures, bar, record):
    """Calls record(future) for each future as it completes (True: done, False: failed), with the progress shown."""
    from dask.distributed import as_completed

    bar.show(_running(client))
    for future in as_completed(futures):
        if record(future):
            bar.done += 1
        else:
            bar.failed += 1
        future.release()
        bar.show(_running(client))


def _drop_failed(path):
    if not path.exists():
        return
    table = ResultsTable(path)
    kept = [r for r in table.rows() if r["status"] != "failed"]
    tmp = path.with_suffix(".csv.tmp")
    with open(tmp, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=RESULT_COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(kept)
        f.flush()
        os.fsync(f.fileno())
    os.replace(tmp, path)


def _study_results(table, study):
    import pandas

    by_key = {r["key"]: r for r in table.rows()}
    rows = [by_key[job["key"]] for job in study if job["key"] in by_key]
    frame = pandas.DataFrame(rows, columns=list(RESULT_COLUMNS))
    for c in ("young", "poisson", "strain", "relative_l2_stretch", "relative_l2_compress", "relative_l2_shear",
              "worst_relative_l2", "held_out_rms", "seconds", "peak_memory_mb"):
        frame[c] = pandas.to_numeric(frame[c], errors="coerce")
    return frame


# ---------------------------------------------------------------------------------------------------------------------
# The nu-range study as batch tasks


def _nu_range_rows(mesh_dir, options, task):
    from . import _hooke

    _tune_malloc()
    return json.loads(_hooke._nu_range_task(str(mesh_dir), options, task))


def nu_range_rows(mesh_dir, options=None, client=None, workers=None, progress=True):
    """The rows of the nu-range study (`hooke reproduce nu-range`), each task (one mesh, plane, load, regime and nu)
    run as a Dask task; returned in the serial study's order, so that the report written from them is the serial
    one. `options`: the study's options as JSON text (default: the library's defaults)."""
    from . import _hooke

    options = options or _hooke._nu_range_default_options()
    tasks = _hooke._nu_range_tasks(str(mesh_dir), options)
    dask_client, close = connect(client, workers)
    bar = _Progress(len(tasks), 0, progress)
    try:
        futures = [dask_client.submit(_nu_range_rows, str(mesh_dir), options, t, pure=False) for t in tasks]
        index = {f.key: i for i, f in enumerate(futures)}
        rows = [None] * len(tasks)

        def record(future):
            rows[index[future.key]] = future.result()  # a task's error is the study's (the serial run raises it)
            return True

        _collect(dask_client, futures, bar, record)
    finally:
        close()
    bar.show(0, final=True)
    return [row for task_rows in rows for row in task_rows]


def nu_range(out_dir, mesh_dir=None, options=None, client=None, workers=None, progress=True):
    """Runs the nu-range study on Dask and writes its report (nu_range.md, nu_range.json, method_table.inc, figure
    specs) to `out_dir`, as `hooke reproduce nu-range` does; returns the recommendations."""
    from . import _hooke

    options = options or _hooke._nu_range_default_options()
    mesh_dir = mesh_dir or _hooke._default_mesh_dir
    start = time.perf_counter()
    rows = nu_range_rows(mesh_dir, options, client, workers, progress)
    return _hooke._nu_range_write(str(out_dir), options, json.dumps(rows), time.perf_counter() - start)


# ---------------------------------------------------------------------------------------------------------------------
# The command line (hooke batch, python3 -m hooke.batch)


def main(argv=None):
    import argparse

    p = argparse.ArgumentParser(prog="hooke batch", description="Runs a study table's jobs on Dask distributed "
                                "(docs/batch.md): results to DIR/results.csv, models to DIR/models/.")
    p.add_argument("study", nargs="?", help="the study table (CSV: name, mesh, young, poisson, method, ...)")
    p.add_argument("-o", "--output", required=True, help="the study folder (or, with --nu-range-rows, the rows file)")
    p.add_argument("--scheduler", default="local",
                   help="a Dask scheduler's address (tcp://host:8786), or 'local' (default): a local cluster")
    p.add_argument("--workers", type=int, default=None, help="local cluster: worker processes (default: one per core)")
    p.add_argument("--retry-failed", action="store_true", help="run again the jobs recorded as failed")
    p.add_argument("--quiet", action="store_true", help="no progress bar")
    p.add_argument("--nu-range-rows", metavar="OPTIONS_JSON", help=argparse.SUPPRESS)  # hooke reproduce nu-range
    p.add_argument("--meshes", help=argparse.SUPPRESS)
    a = p.parse_args(argv)
    if a.workers is not None and a.workers < 1:
        p.error("--workers must be >= 1")
    try:
        if a.nu_range_rows is not None:
            options = pathlib.Path(a.nu_range_rows).read_text()
            rows = nu_range_rows(a.meshes, options, a.scheduler, a.workers, not a.quiet)
            target = pathlib.Path(a.output)
            tmp = target.with_name(target.name + ".tmp")
            tmp.write_text(json.dumps(rows))
            os.replace(tmp, target)
            return 0
        if not a.study:
            p.error("a study table is needed")
        results = run(a.study, a.output, a.scheduler, a.workers, not a.quiet, a.retry_failed)
    except StudyError as e:
        print(f"hooke batch: {e}", file=sys.stderr)
        return 2
    except OSError as e:
        print(f"hooke batch: {e}", file=sys.stderr)
        return 4
    done = int((results["status"] == "ok").sum())
    failed = len(results) - done
    print(f"{len(results)} jobs: {done} certified, {failed} failed; results in "
          f"{pathlib.Path(a.output) / RESULTS_FILE}")
    for _, r in results[results["status"] != "ok"].iterrows():
        print(f"  failed: {r['name']}: {r['error']}")
    return 0 if failed == 0 else 3


if __name__ == "__main__":
    # Run as hooke.batch (not __main__) so that the workers unpickle the module's functions by their import path.
    from hooke.batch import main as _main

    sys.exit(_main())
