"""meshprep batch (issue 47): many parts, each in its own `meshprep pipeline` process, into one
output folder that a killed batch, several shards or a Dask cluster with dying workers leave
complete (OUT/PART only whole) and resumable.

The parts are small closed surfaces: icospheres written here (about a second each) and
tests/data/handle.off (a few seconds, the slow part to kill things under), plus a malformed OFF.
Run by ctest (python_batch) with MESHPREP_BIN=build/bin/meshprep and PYTHONPATH=build/python; the
Dask test is skipped when `distributed` is not importable (apt-get install python3-distributed).
"""

import csv
import json
import math
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from meshprep import batch

HERE = Path(__file__).resolve().parent
DATA = HERE.parent / "data"
BIN = os.environ.get("MESHPREP_BIN", str(HERE.parent.parent / "build" / "bin" / "meshprep"))
TIMEOUT = 300  # seconds for one batch run, far above what they take: a hang fails, not blocks


def write_icosphere(path, level=1, squash=1.0):
    """A closed, FEM-ready surface: an icosahedron subdivided `level` times, flattened along z."""
    golden = (1 + 5 ** 0.5) / 2
    points = [(-1, golden, 0), (1, golden, 0), (-1, -golden, 0), (1, -golden, 0), (0, -1, golden), (0, 1, golden),
              (0, -1, -golden), (0, 1, -golden), (golden, 0, -1), (golden, 0, 1), (-golden, 0, -1), (-golden, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5), (2, 4, 11),
             (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    points = [tuple(c / math.dist(p, (0, 0, 0)) for c in p) for p in points]
    for _ in range(level):
        middles, finer = {}, []

        def middle(a, b):
            if (min(a, b), max(a, b)) not in middles:
                m = [(x + y) / 2 for x, y in zip(points[a], points[b])]
                points.append(tuple(c / math.dist(m, (0, 0, 0)) for c in m))
                middles[min(a, b), max(a, b)] = len(points) - 1
            return middles[min(a, b), max(a, b)]
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    lines = ["OFF", f"{len(points)} {len(faces)} 0"]
    lines += [f"{x} {y} {z * squash}" for x, y, z in points] + [f"3 {a} {b} {c}" for a, b, c in faces]
    Path(path).parent.mkdir(parents=True, exist_ok=True)
    Path(path).write_text("\n".join(lines) + "\n")
    return Path(path)


def write_malformed(path):
    Path(path).write_text("OFF\n3 1 0\n0 0 0\n1 0 garbage\n0 1 0\n3 0 1 2\n")
    return Path(path)


def spheres(folder, count, level=1):
    """`count` different icospheres ball0 ... in folder."""
    return [write_icosphere(folder / f"ball{k}.off", level, squash=0.5 + 0.1 * k) for k in range(count)]


def start_batch(*args):
    return subprocess.Popen([sys.executable, "-m", "meshprep.batch", *map(str, args)], env=batch_env(),
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)


def run_batch(*args):
    return subprocess.run([sys.executable, "-m", "meshprep.batch", *map(str, args)], env=batch_env(),
                          capture_output=True, text=True, timeout=TIMEOUT)


def batch_env():
    return {**os.environ, "MESHPREP_BIN": BIN}


def records(out):
    """{part: its batch.json} of every part folder of OUT."""
    return {d.name: json.loads((d / "batch.json").read_text()) for d in sorted(out.iterdir())
            if d.is_dir() and not d.name.startswith(".")}


def assert_only_complete_parts(out):
    """No hidden partial or replaced folder left, and every part folder has its batch.json."""
    hidden = [d.name for d in out.iterdir() if d.is_dir() and d.name.startswith(".")]
    assert hidden == [], f"left-over folders in {out}: {hidden}"
    for d in out.iterdir():
        if d.is_dir():
            assert (d / "batch.json").is_file(), f"{d} has no batch.json"


def processes_mentioning(text):
    """The pids of the live processes whose command line contains text (a child left writing)."""
    pids = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                if text.encode() in (entry / "cmdline").read_bytes():
                    pids.append(int(entry.name))
            except OSError:
                pass
    return pids


def wait_for(condition, what, timeout=120):
    deadline = time.monotonic() + timeout
    while not condition():
        assert time.monotonic() < deadline, f"timed out waiting for {what}"
        time.sleep(0.05)


def summary_rows(out):
    with open(out / "summary.csv", newline="") as file:
        return list(csv.DictReader(file))


def test_a_local_batch_writes_each_part_whole_and_a_summary_of_them(tmp_path):
    parts = tmp_path / "parts"
    parts.mkdir()
    shutil.copy(DATA / "handle.off", parts)
    write_icosphere(parts / "ball.off", 1, 0.6)
    write_icosphere(parts / "sub" / "egg.OFF", 2, 0.8)  # found recursively, suffix in any case
    write_malformed(parts / "broken.off")
    # Per-part configuration: the CSV's row, then the sidecar beside the input on top.
    (tmp_path / "overrides.csv").write_text("part,tetrahedralize.format,simplify.ratio\n"
                                            "ball,inp,\n"
                                            "egg.OFF,inp,0.5\n")
    (parts / "sub" / "egg.json").write_text('{"tetrahedralize": {"format": "vtu"}}')
    out = tmp_path / "out"

    run = run_batch(parts, "-o", out, "--jobs", 2, "--overrides", tmp_path / "overrides.csv",
                    "--json", tmp_path / "batch.json")

    assert run.returncode == 1, run.stderr  # one part is malformed
    done = records(out)
    assert sorted(done) == ["ball", "broken", "egg", "handle"]
    tets_file = {"ball": "tets.inp", "egg": "tets.vtu", "handle": "tets.msh"}
    for name, tets in tets_file.items():
        record, folder = done[name], out / name
        report = json.loads((folder / "report.json").read_text())
        assert record["exit_code"] == (0 if report["fem_ready"] else 1), record
        assert record["status"] == ("ready" if report["fem_ready"] else "not-ready")
        assert (folder / tets).is_file() and record["tets_file"] == tets
        assert record["figures"]["tets"] == report["tets"]["tet_quality"]["tetrahedra"] > 0
        assert record["figures"]["min_dihedral_deg"] == report["tets"]["tet_quality"]["min_dihedral_deg"]["min"]
        assert (folder / "report.html").is_file() and (folder / "log.txt").is_file()
    # the CSV's simplify.ratio reached egg (matched by its file name) under its sidecar's format
    egg_config = json.loads((out / "egg" / "pipeline.json").read_text())
    assert egg_config["simplify"]["ratio"] == 0.5 and egg_config["tetrahedralize"]["format"] == "vtu"

    broken = done["broken"]
    assert (broken["exit_code"], broken["status"]) == (2, "bad-input")
    assert "garbage" in broken["reason"] and broken["reason"].startswith("meshprep: error: ")
    assert not list((out / "broken").glob("tets.*")) and not (out / "broken" / "report.json").exists()
    assert "garbage" in (out / "broken" / "log.txt").read_text()

    rows = summary_rows(out)
    assert [row["part"] for row in rows] == sorted(done)
    assert {row["part"]: row["status"] for row in rows} == {n: r["status"] for n, r in done.items()}
    assert {row["part"]: row["report"] for row in rows}["handle"] == "handle/report.html"
    summary = json.loads((out / "summary.json").read_text())
    assert [row["part"] for row in summary["parts"]] == sorted(done)
    assert (out / "index.html").read_text().count("<tr class=") == len(done)
    assert json.loads((tmp_path / "batch.json").read_text())["batch"]["exit_code"] == 1
    # one progress line per part
    assert sum(line.startswith("[") for line in run.stderr.splitlines()) == 4
    assert_only_complete_parts(out)


def test_a_batch_of_ready_parts_exits_0_and_names_clashing_stems_apart(tmp_path):
    write_icosphere(tmp_path / "a" / "ball.off", 1, 0.6)
    write_icosphere(tmp_path / "b" / "ball.off", 1, 0.7)
    write_icosphere(tmp_path / "c" / "cap.off", 1, 0.8)
    (tmp_path / "c" / "notes.txt.bak").write_text("not a part")
    # A list (paths relative to it, comments) and a glob pattern, in one batch.
    (tmp_path / "parts.lst").write_text("# the balls\na/ball.off\nb/ball.off  # the second\n\n")
    out = tmp_path / "out"

    run = run_batch(tmp_path / "parts.lst", tmp_path / "c" / "*", "-o", out, "--jobs", 2)

    assert run.returncode == 0, run.stderr
    done = records(out)
    assert sorted(done) == ["ball_off_1", "ball_off_2", "cap"]
    assert done["ball_off_1"]["input"] == str(tmp_path / "a" / "ball.off")  # numbered in path order
    assert all(record["status"] == "ready" for record in done.values())


def test_the_binarys_batch_runs_the_driver_and_passes_the_pipeline_flags_on(tmp_path):
    # `meshprep batch` is a door onto this driver: everything after `--` reaches each part's pipeline.
    spheres(tmp_path / "in", 2)
    out = tmp_path / "out"
    run = subprocess.run([BIN, "batch", *map(str, [tmp_path / "in", "-o", out, "--jobs", 2, "--quiet", "--", "--format", "inp"])],
                         env={k: v for k, v in os.environ.items() if k != "MESHPREP_BIN"}, capture_output=True,
                         text=True, timeout=TIMEOUT)
    assert run.returncode == 0, run.stderr
    assert sorted(records(out)) == ["ball0", "ball1"]
    assert all((out / part / "tets.inp").is_file() for part in ("ball0", "ball1"))


def test_shards_together_run_every_part_once_into_one_folder(tmp_path):
    spheres(tmp_path / "parts", 7)
    out = tmp_path / "out"
    # The three shards at once, as a job array would run them, sharing OUT.
    shards = [start_batch(tmp_path / "parts", "-o", out, "--shard", f"{i}/3", "--jobs", 1, "--threads", 1,
                          "--json", tmp_path / f"shard{i}.json") for i in (1, 2, 3)]
    for shard in shards:
        shard.communicate(timeout=TIMEOUT)
        assert shard.returncode == 0, shard.stderr

    names = sorted(f"ball{k}" for k in range(7))
    ran = [json.loads((tmp_path / f"shard{i}.json").read_text())["batch"]["ran"] for i in (1, 2, 3)]
    assert sorted(sum(ran, [])) == names  # each part in exactly one shard
    for i, shard_parts in enumerate(ran):
        assert sorted(shard_parts) == names[i::3]  # the k-th name in shard k mod 3 + 1
    assert sorted(records(out)) == names
    # The summary is rebuilt from every part folder, whichever shard wrote it.
    rerun = run_batch(tmp_path / "parts", "-o", out, "--shard", "1/3")
    assert rerun.returncode == 0 and "skipped" in rerun.stderr
    assert [row["part"] for row in summary_rows(out)] == names
    assert_only_complete_parts(out)


def test_a_killed_batch_resumes_without_losing_or_half_writing_a_part(tmp_path):
    spheres(tmp_path / "parts", 5, level=2)
    out = tmp_path / "out"
    args = (tmp_path / "parts", "-o", out, "--jobs", 1, "--threads", 1)

    first = start_batch(*args, "--quiet")
    # Kill it (SIGKILL: no cleanup at all) while a part runs, after one has finished.
    wait_for(lambda: out.is_dir() and records(out) and any(".partial-" in d.name for d in out.iterdir()),
             "a finished part and a running one")
    first.kill()
    first.communicate()
    finished = {d.name: (d / "batch.json").read_bytes() for d in out.iterdir()
                if d.is_dir() and not d.name.startswith(".")}
    assert finished
    # Its running child died with it: nothing keeps writing into OUT.
    wait_for(lambda: not processes_mentioning(str(out)), "the killed batch's child to die", timeout=10)

    second = run_batch(*args, "--json", "-")
    assert second.returncode == 0, second.stderr
    this_run = json.loads(second.stdout)["batch"]
    assert sorted(this_run["skipped"]) == sorted(finished)
    assert sorted(this_run["ran"] + this_run["skipped"]) == sorted(f"ball{k}" for k in range(5))
    for name, content in finished.items():
        assert (out / name / "batch.json").read_bytes() == content  # not run again
    assert len(records(out)) == 5
    assert_only_complete_parts(out)  # the killed batch's partial folder is gone

    forced = run_batch(*args, "--force", "--json", "-")
    assert forced.returncode == 0, forced.stderr
    assert json.loads(forced.stdout)["batch"]["skipped"] == []
    assert all((out / name / "batch.json").read_bytes() != content for name, content in finished.items())
    assert_only_complete_parts(out)


@pytest.mark.parametrize("signum, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_stopped_batch_stops_its_children_and_keeps_the_finished_parts(tmp_path, signum, code):
    spheres(tmp_path / "parts", 4, level=2)
    out = tmp_path / "out"
    running = start_batch(tmp_path / "parts", "-o", out, "--jobs", 1, "--threads", 1)
    wait_for(lambda: out.is_dir() and records(out) and any(".partial-" in d.name for d in out.iterdir()),
             "a finished part and a running one")
    kept = {name: record["finished"] for name, record in records(out).items()}

    running.send_signal(signum)
    running.communicate(timeout=60)

    assert running.returncode == code
    assert not processes_mentioning(str(out))
    assert_only_complete_parts(out)
    left = records(out)
    assert all(left[name]["finished"] == finished for name, finished in kept.items())
    assert len(left) < 4 and [row["part"] for row in summary_rows(out)] == sorted(left)


def test_a_part_over_the_memory_cap_is_recorded_and_the_others_go_on(tmp_path):
    parts = tmp_path / "parts"
    write_icosphere(parts / "ball.off", 1)
    write_icosphere(parts / "greedy.off", 1)
    # tets of 1e-8 of the volume each: TetGen runs out of memory under any cap that lets a part run
    (parts / "greedy.json").write_text('{"tetrahedralize": {"max_volume_relative": 1e-8}}')
    out = tmp_path / "out"

    run = run_batch(parts, "-o", out, "--jobs", 2, "--threads", 1, "--max-memory", "250M")

    assert run.returncode == 1, run.stderr
    done = records(out)
    assert done["ball"]["status"] == "ready"
    assert done["greedy"]["status"] == "memory" and done["greedy"]["exit_code"] != 0
    assert not list((out / "greedy").glob("tets.*"))
    # not "done": a rerun (under a larger cap, say) tries it again; here under 1 MB, where the
    # child dies at once, while loading
    again = run_batch(parts, "-o", out, "--max-memory", "1M", "--json", "-")
    assert json.loads(again.stdout)["batch"]["ran"] == ["greedy"]
    assert records(out)["greedy"]["status"] == "memory"


@pytest.fixture
def stand_in(tmp_path):
    """A stand-in for the meshprep binary that answers --version and --print-config and then does
    what $STAND_IN says on `pipeline INPUT`: hang, crash, or fail out of memory."""
    script = tmp_path / "meshprep"
    script.write_text("""#!/bin/sh
case "$*" in
  --version) echo "meshprep 0.0.0"; exit 0 ;;
  *--print-config*) echo "{}"; exit 0 ;;
esac
case "$STAND_IN" in
  hang) exec sleep 600 ;;
  crash) echo "terminate called after throwing an instance of 'std::logic_error'" >&2; kill -ABRT $$ ;;
  memory) echo "meshprep: failed: out of memory" >&2; exit 3 ;;
esac
""")
    script.chmod(0o755)
    return script


def test_a_part_over_its_wall_clock_guard_is_killed_and_recorded_as_timed_out(tmp_path, stand_in, monkeypatch):
    part = write_icosphere(tmp_path / "ball.off")
    out = tmp_path / "out"
    out.mkdir()
    monkeypatch.setenv("STAND_IN", "hang")
    settings = {"out": str(out), "meshprep": str(stand_in), "version": "meshprep 0.0.0", "flags": [],
                "threads": 1, "time_limit": None, "guard_seconds": 1.0, "max_memory": None, "force": False}
    start = time.monotonic()

    record = batch.run_part({"name": "ball", "input": str(part), "config": {}}, settings)

    assert time.monotonic() - start < 1.0 + batch.TERMINATE_GRACE_SECONDS
    assert (record["exit_code"], record["status"]) == (124, "timeout")
    assert "guard" in record["reason"]
    assert not processes_mentioning(str(out))
    assert json.loads((out / "ball" / "batch.json").read_text()) == record
    assert_only_complete_parts(out)


@pytest.mark.parametrize("behaviour, status, exit_code", [("crash", "crashed", -signal.SIGABRT),
                                                          ("memory", "memory", 3)])
def test_a_child_that_crashes_or_runs_out_of_memory_is_recorded_so(tmp_path, stand_in, behaviour, status,
                                                                   exit_code, monkeypatch):
    write_icosphere(tmp_path / "parts" / "ball.off")
    monkeypatch.setenv("STAND_IN", behaviour)
    out = tmp_path / "out"

    run = run_batch(tmp_path / "parts", "-o", out, "--meshprep", stand_in)

    assert run.returncode == 1, run.stderr
    record = records(out)["ball"]
    assert (record["status"], record["exit_code"]) == (status, exit_code)
    assert record["reason"]


@pytest.mark.parametrize("args, message", [
    (["EMPTY"], "no mesh or point file"),
    (["MISSING.stl"], "no such file"),
    (["PARTS/*.obj"], "no file matches"),
    (["PARTS", "--shard", "4/3"], "--shard 4/3"),
    (["PARTS", "--shard", "0/2"], "--shard 0/2"),
    (["PARTS", "--shard", "one"], "--shard one"),
    (["PARTS", "--jobs", "0"], "--jobs 0"),
    (["PARTS", "--max-memory", "lots"], "--max-memory lots"),
    (["PARTS", "--config", "TYPO.json"], "unknown key 'simplify.ratoi'"),
    (["PARTS", "--overrides", "NOPART.csv"], "no 'part' column"),
    (["PARTS", "--", "-o", "elsewhere"], "-o after --"),
    (["PARTS", "--", "--no-such-flag"], "--no-such-flag"),
    ([], "no input"),
])
def test_bad_usage_exits_2_with_one_line_and_writes_nothing(tmp_path, args, message):
    write_icosphere(tmp_path / "parts" / "ball.off")
    (tmp_path / "empty").mkdir()
    (tmp_path / "typo.json").write_text('{"simplify": {"ratoi": 0.2}}')
    (tmp_path / "nopart.csv").write_text("name,simplify.ratio\nball,0.5\n")
    names = {"EMPTY": "empty", "MISSING.stl": "missing.stl", "PARTS": "parts", "TYPO.json": "typo.json",
             "NOPART.csv": "nopart.csv"}
    for placeholder, name in names.items():
        args = [arg.replace(placeholder, str(tmp_path / name)) for arg in args]
    out = tmp_path / "out"

    run = run_batch("-o", out, *args)

    assert run.returncode == 2
    assert run.stderr.count("\n") == 1 and run.stderr.startswith("meshprep: error: "), run.stderr
    assert message in run.stderr
    assert not out.exists()


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # tornado's, under LocalCluster
def test_on_a_dask_cluster_a_part_whose_worker_is_killed_runs_again(tmp_path):
    distributed = pytest.importorskip(
        "distributed", reason="distributed is not importable (apt-get install python3-distributed)")
    parts = tmp_path / "parts"
    spheres(parts, 4)
    shutil.copy(DATA / "handle.off", parts)
    write_malformed(parts / "broken.off")
    out = tmp_path / "out"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        worker_pids = set(client.run(os.getpid).values())
        running = start_batch(parts, "-o", out, "--scheduler", cluster.scheduler_address)
        # handle.off, the largest part, starts first and runs for seconds: kill the worker running it.
        def partial_of_handle():
            return next((d for d in out.glob(".handle.partial-*")), None) if out.is_dir() else None
        wait_for(partial_of_handle, "handle.off to start on a worker")
        killed_pid = int(partial_of_handle().name.split("partial-")[1].split("@")[0])
        assert killed_pid in worker_pids
        os.kill(killed_pid, signal.SIGKILL)
        stdout, stderr = running.communicate(timeout=TIMEOUT)

    assert running.returncode == 1, stderr  # the malformed part
    done = records(out)
    assert sorted(done) == ["ball0", "ball1", "ball2", "ball3", "broken", "handle"]
    handle = done["handle"]
    assert handle["exit_code"] in (0, 1) and (out / "handle" / handle["tets_file"]).is_file()
    assert not handle["runner"].startswith(f"{killed_pid}@")  # run again, by another worker process
    assert (done["broken"]["exit_code"], done["broken"]["status"]) == (2, "bad-input")
    assert all(done[f"ball{k}"]["status"] == "ready" for k in range(4))
    assert not processes_mentioning(f"partial-{killed_pid}@")  # the killed worker's child died with it
    assert_only_complete_parts(out)


def test_on_a_dask_cluster_a_killed_batch_resumes_where_it_stopped(tmp_path):
    distributed = pytest.importorskip(
        "distributed", reason="distributed is not importable (apt-get install python3-distributed)")
    parts = tmp_path / "parts"
    spheres(parts, 4, level=2)
    shutil.copy(DATA / "handle.off", parts)
    write_malformed(parts / "broken.off")
    out = tmp_path / "out"
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        args = (parts, "-o", out, "--scheduler", cluster.scheduler_address)
        first = start_batch(*args, "--quiet")
        wait_for(lambda: out.is_dir() and records(out), "a finished part")
        first.kill()  # SIGKILL: the batch leaves no word; what its workers were running may still finish
        first.communicate()
        finished = {d.name: (d / "batch.json").read_bytes() for d in out.iterdir()
                    if d.is_dir() and not d.name.startswith(".")}
        wait_for(lambda: not any(client.processing().values()) and not list(out.glob(".*.partial-*")),
                 "the cluster to finish what the killed batch had started")

        second = run_batch(*args, "--json", "-")

    assert second.returncode == 1, second.stderr  # the malformed part
    this_run = json.loads(second.stdout)["batch"]
    assert sorted(this_run["ran"] + this_run["skipped"]) == ["ball0", "ball1", "ball2", "ball3", "broken", "handle"]
    assert set(finished) - {"broken"} <= set(this_run["skipped"])
    for name, content in finished.items():
        if name != "broken":  # a part with nothing written runs again; the others are kept
            assert (out / name / "batch.json").read_bytes() == content
    done = records(out)
    assert all(done[name]["exit_code"] in (0, 1) for name in done if name != "broken")
    assert done["broken"]["exit_code"] == 2
    assert_only_complete_parts(out)
