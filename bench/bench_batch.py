"""Benchmark of hooke.batch on Dask distributed: the nu-range study's linear grid (every mesh, plane, load and nu at
0.1 % strain against the linear FEM, `hooke reproduce nu-range --large-strain 0`) run serially in this process and on
local clusters of 1 and 2 worker processes, with the parallel efficiency T(1 worker) / (2 T(2 workers)) and a check
that every row equals the serial one; and the overhead per task (empty jobs on 1 worker).

Usage: PYTHONPATH=build/release/python /usr/bin/python3 bench/bench_batch.py [--repeat N] [--nu 0,0.1,...] [-o FILE]
Prints a Markdown table (medians over N runs, default 1) and writes it to FILE (default out/bench_batch.md).
"""
import argparse
import json
import pathlib
import statistics
import sys
import time


def empty_task(i):
    return i


def main():
    from hooke import _hooke, batch

    p = argparse.ArgumentParser()
    p.add_argument("--repeat", type=int, default=1)
    p.add_argument("--nu", default=None, help="Poisson's ratios (default: the study's)")
    p.add_argument("--empty-tasks", type=int, default=400)
    p.add_argument("-o", "--output", default="out/bench_batch.md")
    a = p.parse_args()

    options = json.loads(_hooke._nu_range_default_options())
    options["large_strain"] = 0.0
    if a.nu:
        options["poisson"] = [float(x) for x in a.nu.split(",")]
    options = json.dumps(options)
    mesh_dir = _hooke._default_mesh_dir
    tasks = _hooke._nu_range_tasks(mesh_dir, options)

    # Serial in this process (one OpenMP thread per task's solve as on a worker is not enforced here: the reference
    # for the rows, not for the time).
    t0 = time.perf_counter()
    serial = [row for t in tasks for row in json.loads(_hooke._nu_range_task(mesh_dir, options, t))]
    serial_s = time.perf_counter() - t0

    times = {}
    for workers in (1, 2):
        runs = []
        for _ in range(a.repeat):
            cluster = batch.local_cluster(workers)  # started before the clock: a cluster serves many studies
            try:
                t0 = time.perf_counter()
                rows = batch.nu_range_rows(mesh_dir, options, client=cluster.scheduler_address, progress=False)
                runs.append(time.perf_counter() - t0)
            finally:
                cluster.close()
            if rows != serial:
                print(f"rows on {workers} workers differ from the serial rows", file=sys.stderr)
                return 1
        times[workers] = statistics.median(runs)

    # Overhead per task: empty tasks through one worker, submitted together, as the study submits.
    cluster = batch.local_cluster(1)
    from dask.distributed import Client, wait

    client = Client(cluster)
    try:
        client.submit(empty_task, -1).result()  # warm
        t0 = time.perf_counter()
        futures = [client.submit(empty_task, i, pure=False) for i in range(a.empty_tasks)]
        wait(futures)
        overhead = (time.perf_counter() - t0) / a.empty_tasks
    finally:
        client.close()
        cluster.close()

    efficiency = times[1] / (2.0 * times[2])
    per_task = times[1] / len(tasks)
    lines = [
        f"nu-range linear grid: {len(tasks)} tasks ({len(serial)} comparisons), medians of {a.repeat} run(s)",
        "",
        "| run | wall s | parallel efficiency |",
        "|---|---|---|",
        f"| serial, in process | {serial_s:.1f} | - |",
        f"| Dask, 1 worker | {times[1]:.1f} | - |",
        f"| Dask, 2 workers | {times[2]:.1f} | {efficiency:.3f} |",
        "",
        f"Rows on 1 and 2 workers equal the serial rows: yes. Mean task {per_task:.2f} s; overhead per empty task "
        f"{1e3 * overhead:.2f} ms ({a.empty_tasks} tasks on 1 worker).",
    ]
    text = "\n".join(lines) + "\n"
    print(text)
    out = pathlib.Path(a.output)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
