"""hooke.batch on a Dask LocalCluster of 2 worker processes: a study equals the serial results, a worker killed with
SIGKILL mid-task loses nothing and duplicates nothing, a malformed mesh is recorded as failed with its ParseError
text, a rerun runs nothing."""
import csv
import os
import pathlib
import signal
import time

import pytest

import hooke

distributed = pytest.importorskip("distributed")
from hooke import batch  # noqa: E402


@pytest.fixture(scope="module")
def cluster():
    c = batch.local_cluster(workers=2)
    yield c
    c.close()


@pytest.fixture(scope="module")
def client(cluster):
    # One Client per process: distributed 2022.12's clients share an event loop, and a second one in another thread
    # binds the first one's futures to its loop.
    c = distributed.Client(cluster)
    yield c
    c.close()


def study(meshes, tmp_path, bad=False):
    jobs = [{"mesh": str(meshes / "cylinder.msh"), "young": 14630.0, "poisson": nu, "method": method}
            for nu in (0.2, 0.3, 0.4, 0.45) for method in ("lloyd-tet", "any-nu-tet", "stiffness-fit-volume")]
    if bad:
        path = tmp_path / "broken.msh"
        path.write_text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\nnot-a-count\n")
        jobs.insert(5, {"mesh": str(path), "young": 14630.0, "poisson": 0.45, "method": "any-nu-tet"})
    return jobs


def rows(out):
    with open(out / "results.csv", newline="") as f:
        return list(csv.DictReader(f))


def test_a_study_on_two_workers_equals_the_serial_results_and_records_a_malformed_mesh(meshes, tmp_path, client):
    jobs = study(meshes, tmp_path, bad=True)
    out = tmp_path / "study"
    results = batch.run(jobs, out, client=client, progress=False)
    assert len(results) == 13 and len(rows(out)) == 13
    failed = results[results["status"] == "failed"]
    assert list(failed["mesh"]) == [str(tmp_path / "broken.msh")]
    assert failed["error"].iloc[0].startswith("ParseError: " + str(tmp_path / "broken.msh") + ":5:")
    ok = results[results["status"] == "ok"]
    assert len(ok) == 12 and ok["worker"].nunique() == 2  # both workers took jobs
    # The same jobs run here, one after another, give the same numbers (the workers run one OpenMP thread, this
    # process may run more: sums may differ in the last bits).
    serial_out = tmp_path / "serial"
    for job in batch._jobs_from(jobs):
        if job["mesh"].endswith("broken.msh"):
            continue
        job["key"] = batch.job_key(job)
        expected = batch.run_job(job, serial_out)
        got = ok[ok["key"] == job["key"]].iloc[0]
        assert expected["status"] == "ok" and got["method_used"] == expected["method_used"]
        for load in ("stretch", "compress", "shear"):
            assert got["relative_l2_" + load] == pytest.approx(expected["relative_l2_" + load], rel=1e-9)
        model = hooke.read_model(out / got["model"])
        assert model.method == job["method"] and len(model.certificate) == 3
    # Models differ with nu (but Lloyd's, whose springs ignore nu): the table is not one result copied.
    assert ok[ok["method"] != "lloyd-tet"]["relative_l2_stretch"].nunique() == 8


def test_a_rerun_runs_nothing(meshes, tmp_path, client):
    jobs = study(meshes, tmp_path)[:4]
    out = tmp_path / "study"
    first = batch.run(jobs, out, client=client, progress=False)
    before = (out / "results.csv").read_bytes()

    class NoCluster:
        def submit(self, *args, **kwargs):
            raise AssertionError("a rerun submitted a task")

    again = batch.run(jobs, out, client=NoCluster(), progress=False)
    assert (out / "results.csv").read_bytes() == before
    assert list(again["key"]) == list(first["key"])
    # A changed mesh file is a new job (its bytes are in the key).
    (tmp_path / "elsewhere").mkdir()
    copy = tmp_path / "elsewhere" / "cylinder.msh"
    copy.write_bytes((meshes / "cylinder.msh").read_bytes())
    changed = [dict(jobs[0], mesh=str(copy))]
    key = batch.job_key(batch._jobs_from(changed)[0])
    assert key == first["key"].iloc[0]  # same bytes, same name: the same job
    copy.write_bytes((meshes / "cylinder.msh").read_bytes() + b"\n")
    assert batch.job_key(batch._jobs_from(changed)[0]) != key


def test_a_worker_killed_mid_task_loses_and_duplicates_nothing(meshes, tmp_path, client):
    # The study runs in its own process (python3 -m hooke.batch, connected to this cluster's scheduler) while this one
    # watches the workers: two slow jobs among fast ones, one killed mid-task with SIGKILL. The slow jobs are a
    # 6 525-node box (2-4 s each): the 990-node cylinder_hole now calibrates and certifies in 0.4 s, so that the
    # kill, 0.5 s into the task, came after its result and the test measured nothing.
    import subprocess
    import sys

    box = tmp_path / "box.vtu"
    hooke.write_mesh(str(box), hooke.tet_box(0.02, 0.02, 0.04, 14, 14, 28))
    table = tmp_path / "study.csv"
    lines = ["name,mesh,young,poisson,method"]
    lines += [f"fast-{nu}-{m},{meshes / 'cylinder.msh'},14630,{nu},{m}" for nu in (0.2, 0.3, 0.45)
              for m in ("lloyd-tet", "any-nu-tet")]
    lines += [f"slow-{nu},{box},14630,{nu},any-nu-tet" for nu in (0.3, 0.45)]
    table.write_text("\n".join(lines) + "\n")
    jobs = batch.read_study(table)
    keys = {batch.job_key(j) for j in jobs}
    slow = {"hooke-job-" + batch.job_key(j) for j in jobs if j["name"].startswith("slow")}
    out = tmp_path / "study"
    study = subprocess.Popen([sys.executable, "-m", "hooke.batch", str(table), "-o", str(out), "--scheduler",
                              client.scheduler.address, "--quiet"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True)
    killed = None
    deadline = time.monotonic() + 120
    while killed is None and time.monotonic() < deadline and study.poll() is None:
        for address, tasks in client.processing().items():
            if any(t in slow for t in tasks):
                time.sleep(0.5)  # well inside the task
                killed = client.run(os.getpid, workers=[address])[address]
                os.kill(killed, signal.SIGKILL)
                break
        time.sleep(0.05)
    stdout, stderr = study.communicate(timeout=300)
    assert killed is not None, "no worker was killed: the test did not test anything"
    assert study.returncode == 0, stdout + stderr
    table_rows = rows(out)
    assert sorted(r["key"] for r in table_rows) == sorted(keys)  # every result, exactly once
    assert all(r["status"] == "ok" for r in table_rows), table_rows
    assert all(not r["worker"].endswith(f":{killed}") for r in table_rows if r["name"].startswith("slow"))
    client.wait_for_workers(2, timeout=60)  # the nanny restarted the killed worker


def test_a_torn_last_line_is_dropped_and_the_job_rerun(meshes, tmp_path, client):
    jobs = study(meshes, tmp_path)[:2]
    out = tmp_path / "study"
    batch.run(jobs, out, client=client, progress=False)
    text = (out / "results.csv").read_text()
    (out / "results.csv").write_text(text[: len(text) - 40])  # a run killed while writing its last result
    results = batch.run(jobs, out, client=client, progress=False)
    assert (results["status"] == "ok").all() and len(rows(out)) == 2


def test_a_malformed_study_table_names_the_line(tmp_path):
    table = tmp_path / "study.csv"
    table.write_text("mesh,young,poisson\ncylinder.msh,14630,0.3\ncylinder.msh,soft,0.3\n")
    with pytest.raises(batch.StudyError, match=r"study.csv:3: column 'young' is 'soft', not a number"):
        batch.read_study(table)
    table.write_text("mesh,young,poisson,colour\ncylinder.msh,14630,0.3,red\n")
    with pytest.raises(batch.StudyError, match="unknown column"):
        batch.read_study(table)


def test_hooke_batch_on_the_command_line(meshes, tmp_path):
    cli = os.environ.get("HOOKE_CLI")
    if not cli:
        pytest.skip("HOOKE_CLI not set")
    import subprocess

    table = tmp_path / "study.csv"
    table.write_text(f"name,mesh,young,poisson,method\nc,{meshes / 'cylinder.msh'},14630,0.45,any-nu-tet\n"
                     f"t,{meshes / 'rectangle_tri.msh'},14630,0.3,any-nu-triangle\n"
                     f"i,{meshes / 'cylinder.msh'},14630,0.45,identify\n")
    run = subprocess.run([cli, "batch", str(table), "-o", str(tmp_path / "out"), "--workers", "1", "--quiet"],
                         capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    assert "3 jobs: 3 certified, 0 failed" in run.stdout
    table = {r["name"]: r for r in rows(tmp_path / "out")}
    assert len(table) == 3
    # The identified model (Eq. 1 from the Eq. 2 fit) carries its held-out error and its certificate.
    assert table["i"]["method_used"] == "identified" and 0.0 < float(table["i"]["held_out_rms"]) < 0.1
    assert 0.0 < float(table["i"]["worst_relative_l2"]) < 0.1
    bad = subprocess.run([cli, "batch", str(tmp_path / "missing.csv"), "-o", str(tmp_path / "o2")],
                         capture_output=True, text=True)
    assert bad.returncode == 4 and "missing.csv" in bad.stderr


def test_reproduce_nu_range_on_dask_writes_the_serial_report(tmp_path):
    cli = os.environ.get("HOOKE_CLI")
    if not cli:
        pytest.skip("HOOKE_CLI not set")
    import json
    import re
    import subprocess

    # cylinder_hole is large enough for CHOLMOD's supernodal factorisation to call the BLAS, whose thread count would
    # change the last bits (the study runs it on one thread: core/blas_threads.hpp).
    grid = ["--nu", "0.45", "--study-meshes", "cylinder_hole,rectangle_tri", "--large-strain", "0", "--laws", "none",
            "--no-figures"]
    serial = subprocess.run([cli, "reproduce", "nu-range", "-o", str(tmp_path / "serial")] + grid,
                            capture_output=True, text=True)
    assert serial.returncode == 0, serial.stderr
    dask = subprocess.run([cli, "reproduce", "nu-range", "-o", str(tmp_path / "dask"), "--scheduler", "local"] + grid,
                          capture_output=True, text=True)
    assert dask.returncode == 0, dask.stderr
    a, b = tmp_path / "serial", tmp_path / "dask"
    assert (a / "method_table.inc").read_bytes() == (b / "method_table.inc").read_bytes()
    ja, jb = json.loads((a / "nu_range.json").read_text()), json.loads((b / "nu_range.json").read_text())
    assert len(ja["rows"]) == 3 * 5 + 2 * 3 * 4  # tets, and triangles in two planes
    ja.pop("seconds"), jb.pop("seconds")
    assert ja == jb  # every number, to the last bit (JSON doubles round-trip)
    # The Markdown differs in the study's wall time alone.
    time_free = [re.sub(r"comparisons in \d+ s", "comparisons in T s", (d / "nu_range.md").read_text()) for d in (a, b)]
    assert time_free[0] == time_free[1]
    for d in (a, b):
        specs = sorted(p.name for p in (d / "figures").glob("*.json"))
        assert len(specs) == 1
    assert [p.read_bytes() for p in sorted((a / "figures").glob("*.json"))] == \
        [p.read_bytes() for p in sorted((b / "figures").glob("*.json"))]


def test_python_nu_range_on_dask_writes_the_report(meshes, tmp_path, client):
    # hooke.batch.nu_range from Python, on the test's cluster: the same rows as the library's serial tasks.
    import json

    from hooke import _hooke

    options = json.loads(_hooke._nu_range_default_options())
    # with a law regime: its tasks (one per mesh and nu, fitting every method's law) travel as JSON too
    options.update(poisson=[0.3], meshes=["cylinder"], large_strain=0.0, laws=[{"law": "neohookean", "strain": 0.2}],
                   fit_refinements=0)
    options = json.dumps(options)
    picks = batch.nu_range(tmp_path, meshes, options, client=client, progress=False)
    report = json.loads((tmp_path / "nu_range.json").read_text())
    serial = [row for t in _hooke._nu_range_tasks(str(meshes), options)
              for row in json.loads(_hooke._nu_range_task(str(meshes), options, t))]
    assert report["rows"] == serial and len(serial) == 3 * 5 + 3 * 5 * 2  # traction; Hookean and fitted per load
    fitted = [r for r in serial if r["term_law"] == "fitted"]
    assert len(fitted) == 15 and all(r["control"] == "displacement" and r["force_error"] >= 0 for r in fitted)
    assert len(picks) == 2 and picks[0].startswith("tet, nu = 0.3: ")
    assert picks[1].startswith("tet, nu = 0.3, neohookean FEM at 20 % strain, displacement control: ")
    assert (tmp_path / "method_table.inc").exists() and (tmp_path / "nu_range.md").exists()
