"""meshprep batch: `meshprep pipeline` on many parts, locally or on a Dask cluster (docs/batch.md).

    python3 -m meshprep.batch parts/ more.lst 'cad/*.stl' -o out --jobs 4 [-- PIPELINE_FLAGS...]

Each part runs as its own child process (a crash takes down one part, never the batch) into a
hidden folder OUT/.PART.partial-PID@HOST-TOKEN; once the child has ended and the part's batch.json
is written there, the folder is renamed to OUT/PART. So OUT/PART exists only complete, and a batch
killed at any moment loses no finished part: run it again and the parts whose batch.json matches
(same input bytes, configuration, flags and meshprep version, exit 0 or 1) are skipped.
OUT/summary.csv, summary.json and index.html are rebuilt from every OUT/*/batch.json as parts
finish, so they also hold the parts of earlier runs and of other shards writing into OUT.

Standard library only; Dask's `distributed` is imported only for --scheduler. The work is done by
the `meshprep` binary (--meshprep, else $MESHPREP_BIN, else `meshprep` on PATH), not by the
extension module.
"""

import argparse
import concurrent.futures
import csv
import ctypes
import errno
import fcntl
import glob
import hashlib
import html
import json
import os
import re
import resource
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse
from datetime import datetime, timezone
from pathlib import Path

MESH_SUFFIXES = (".off", ".obj", ".ply", ".stl", ".xyz")
LIST_SUFFIXES = (".txt", ".lst")
# Files of OUT itself; a part may not take their names.
SUMMARY_FILES = ("summary.csv", "summary.json", "index.html")
# The pipeline flags the batch sets itself, or that would make the child do something else.
FLAGS_THE_BATCH_SETS = ("-o", "--output", "--config", "--json", "--quiet", "--threads", "--time-limit",
                        "--print-config", "--config-keys", "-h", "--help")

# The waiting thread touches its part's partial folder this often; a folder untouched for
# STALE_AFTER_SECONDS belongs to a batch that is gone (on any host sharing OUT).
HEARTBEAT_SECONDS = 60
STALE_AFTER_SECONDS = 600
POLL_SECONDS = 1.0             # how soon a stop (Ctrl-C, the time guard) reaches a waiting child
TERMINATE_GRACE_SECONDS = 10   # after SIGTERM, before SIGKILL
# The wall-clock guard on a part, given --time-limit S: S x 1.5 + 30 s (the child stops itself at
# S; the guard is for a child that does not).
GUARD_FACTOR = 1.5
GUARD_MARGIN_SECONDS = 30
DASK_RETRIES = 2               # a part whose run_part raised (a file-system hiccup) runs again

# Exit codes of `meshprep pipeline` (the command-line contract) and the status word of each.
EXIT_STATUS = {0: "ready", 1: "not-ready", 2: "bad-input", 3: "failed", 124: "timeout", 130: "interrupted",
               143: "interrupted"}
# What a child out of memory prints: the binary's own message, an uncaught std::bad_alloc, the
# loader or a thread failing to map memory under RLIMIT_AS.
OUT_OF_MEMORY = re.compile(r"out of memory|bad_alloc|cannot allocate memory|failed to map segment|"
                           r"pthread_create", re.IGNORECASE)
# A part's hidden folder in OUT while it is written (.PART.partial-PID@HOST-TOKEN) or replaced
# (.PART.old-...): the owner's pid and host tell whether it is still being written.
PARTIAL_NAME = re.compile(r"^\.(?P<part>.+)\.(?:partial|old)-(?P<pid>\d+)@(?P<host>.+)-(?P<token>[0-9a-f]{8})$")

_libc = ctypes.CDLL(None, use_errno=True)  # for prctl, which Python's os module lacks
PR_SET_PDEATHSIG = 1  # <linux/prctl.h>


class UsageError(Exception):
    """Bad batch usage or inputs: one line on stderr, exit 2, nothing written."""


class Stopped(Exception):
    """The batch was told to stop (SIGINT, SIGTERM); code is its exit code."""

    def __init__(self, code):
        super().__init__(code)
        self.code = code


# ---------------------------------------------------------------------------------------------
# Inputs and part names


def collect_inputs(specs, out_dir):
    """The mesh and point files that the command line's inputs name, each once (resolved paths)."""
    found = {}
    for spec in specs:
        _collect(spec, Path.cwd(), out_dir.resolve(), found, set(), where=spec)
    return list(found)


def _collect(spec, base, out_dir, found, lists_seen, where):
    path = Path(spec).expanduser()
    path = path if path.is_absolute() else base / path
    if path.is_dir():
        _scan_folder(path, out_dir, found)
    elif path.is_file():
        suffix = path.suffix.lower()
        if suffix in LIST_SUFFIXES:
            _read_list(path.resolve(), out_dir, found, lists_seen)
        elif suffix in MESH_SUFFIXES:
            found.setdefault(path.resolve(), None)
        else:
            raise UsageError(f"{where}: not a mesh or point file ({' '.join(MESH_SUFFIXES)}) "
                             f"nor a list of them ({' '.join(LIST_SUFFIXES)})")
    elif glob.has_magic(str(spec)):
        matches = sorted(glob.glob(str(path), recursive=True))
        if not matches:
            raise UsageError(f"{where}: no file matches")
        for match in map(Path, matches):
            if match.is_dir():
                _scan_folder(match, out_dir, found)
            elif match.suffix.lower() in MESH_SUFFIXES:
                found.setdefault(match.resolve(), None)
    else:
        raise UsageError(f"{where}: no such file or folder")


def _scan_folder(folder, out_dir, found):
    """The folder's mesh and point files, recursively; hidden entries and the batch's OUT left out."""
    for root, dirs, files in os.walk(folder):
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and Path(root, d).resolve() != out_dir)
        for name in sorted(files):
            if not name.startswith(".") and Path(name).suffix.lower() in MESH_SUFFIXES:
                found.setdefault(Path(root, name).resolve(), None)


def _read_list(list_path, out_dir, found, lists_seen):
    """One path (file, folder, glob or list) per line, relative to the list's folder; # comments."""
    if list_path in lists_seen:
        return
    lists_seen.add(list_path)
    try:
        lines = list_path.read_text().splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise UsageError(f"{list_path}: cannot read: {error}") from None
    for number, line in enumerate(lines, start=1):
        entry = line.split("#", 1)[0].strip()
        if entry:
            _collect(entry, list_path.parent, out_dir, found, lists_seen, where=f"{list_path}:{number}: {entry}")


def name_parts(paths):
    """{path: part name}: the file's stem, made unique deterministically (the same inputs give the
    same names in every run and shard): stems shared by several inputs become STEM_EXT, and names
    still shared get _1, _2, ... in the order of their paths."""
    def clean(stem):  # a leading dot would hide the folder and mimic a partial one
        return "_" + stem[1:] if stem.startswith(".") else stem

    stems = {}
    for path in paths:
        stems.setdefault(clean(path.stem), []).append(path)
    candidates = {}
    for stem, same in stems.items():
        for path in same:
            ext = path.suffix.lstrip(".").lower()
            clash = len(same) > 1 or stem in SUMMARY_FILES
            candidates[path] = f"{stem}_{ext}" if clash else stem
    counts = {}
    for name in candidates.values():
        counts[name] = counts.get(name, 0) + 1
    taken = {name for name, n in counts.items() if n == 1}
    names = {}
    for path in sorted(paths):
        name = candidates[path]
        if counts[name] > 1:
            number = 1
            while f"{name}_{number}" in taken:
                number += 1
            name = f"{name}_{number}"
            taken.add(name)
        names[path] = name
    return names


def parse_shard(text):
    """'I/N' -> (I, N), 1 <= I <= N."""
    match = re.fullmatch(r"(\d+)/(\d+)", text.strip())
    if not match or not 1 <= int(match[1]) <= int(match[2]):
        raise UsageError(f"--shard {text}: expected I/N with 1 <= I <= N (e.g. 2/8)")
    return int(match[1]), int(match[2])


def in_shard(names_sorted, shard):
    """The names of shard I/N: the k-th name (0-based, sorted) belongs to shard (k mod N) + 1."""
    index, count = shard
    return [name for k, name in enumerate(names_sorted) if k % count + 1 == index]


def parse_size(text):
    """'4G', '512M', '100k', '1.5GiB', '2000000' -> bytes (K, M, G, T are powers of 1024)."""
    match = re.fullmatch(r"\s*(\d+(?:\.\d+)?)\s*([kmgt]?)(?:i?b)?\s*", text, re.IGNORECASE)
    if not match:
        raise UsageError(f"--max-memory {text}: expected a size such as 4G, 512M or 2000000 (bytes)")
    scale = 1024 ** " kmgt".index((match[2] or " ").lower())
    size = int(float(match[1]) * scale)
    if size <= 0:
        raise UsageError(f"--max-memory {text}: must be positive")
    return size


# ---------------------------------------------------------------------------------------------
# Configuration: --config, then the --overrides CSV row, then the sidecar PART.json


def merge(base, over):
    """base with over's values on top, section by section (neither is changed)."""
    merged = dict(base)
    for key, value in over.items():
        if isinstance(value, dict) and isinstance(merged.get(key), dict):
            merged[key] = merge(merged[key], value)
        else:
            merged[key] = value
    return merged


def set_dotted(config, dotted_key, value):
    """config['simplify']['ratio'] = value for 'simplify.ratio'."""
    *sections, key = dotted_key.split(".")
    for section in sections:
        config = config.setdefault(section, {})
    config[key] = value


def parse_cell(text):
    """A CSV cell: JSON when it parses as JSON (0.2, true, [200,200], "x"), else the text itself."""
    def no_constants(name):  # NaN and Infinity are not JSON the binary reads
        raise ValueError(name)
    try:
        return json.loads(text, parse_constant=no_constants)
    except ValueError:
        return text


def read_json_object(path, what):
    try:
        value = json.loads(Path(path).read_text())
    except OSError as error:
        raise UsageError(f"{path}: cannot read {what}: {error.strerror}") from None
    except ValueError as error:
        raise UsageError(f"{path}: {what} is not valid JSON: {error}") from None
    if not isinstance(value, dict):
        raise UsageError(f"{path}: {what} must be a JSON object of sections, e.g. {{\"simplify\": {{\"ratio\": 0.2}}}}")
    return value


def read_overrides(csv_path, inputs_by_name):
    """{part name: sectioned config} from a CSV with a `part` column (a part name or an input's
    file name) and one column per dotted key; empty cells are left out. Also the columns' keys."""
    try:
        with open(csv_path, newline="", encoding="utf-8-sig") as file:  # -sig: a spreadsheet's BOM
            reader = csv.DictReader(file)
            rows = list(reader)
            columns = [column.strip() for column in reader.fieldnames or []]
    except (OSError, UnicodeDecodeError, csv.Error) as error:
        raise UsageError(f"{csv_path}: cannot read: {error}") from None
    if "part" not in columns:
        raise UsageError(f"{csv_path}: no 'part' column (a part name or an input's file name per row)")
    keys = [c for c in columns if c and c != "part"]
    overrides, unmatched = {}, []
    for line, row in enumerate(rows, start=2):
        row = {(k or "").strip(): (v or "").strip() for k, v in row.items() if k is not None}
        who = row.get("part", "")
        if not who:
            continue
        config = {}
        for key in keys:
            if row.get(key):
                set_dotted(config, key, parse_cell(row[key]))
        targets = [name for name, path in inputs_by_name.items() if who in (name, path.name)]
        if not targets:
            unmatched.append(who)
        for name in targets:
            if name in overrides:
                raise UsageError(f"{csv_path}:{line}: part {name} has a second row")
            overrides[name] = config
    return overrides, keys, unmatched


# ---------------------------------------------------------------------------------------------
# One part (run here or on a Dask worker; plain arguments, importable as meshprep.batch.run_part)


def part_hash(input_path, config, flags, version):
    """sha256 of what decides a part's result: its input's bytes, its merged configuration
    (canonical JSON), the pass-through flags and `meshprep --version`."""
    digest = hashlib.sha256()
    with open(input_path, "rb") as file:
        for block in iter(lambda: file.read(1 << 20), b""):
            digest.update(block)
    for piece in (json.dumps(config, sort_keys=True, separators=(",", ":")), json.dumps(list(flags)), version):
        digest.update(b"\0" + piece.encode())
    return digest.hexdigest()


def _hash_if_readable(part, settings):
    try:
        return part_hash(part["input"], part["config"], settings["flags"], settings["version"])
    except OSError:
        return None


def _owner_tag():
    return f"{os.getpid()}@{socket.gethostname()}-{secrets.token_hex(4)}"


def _child_setup(max_memory, parent_pid):
    """Runs in the child between fork and exec: die with the parent (SIGKILL when the thread that
    started it ends: the batch or the Dask worker was killed), and the memory cap."""
    def setup():
        _libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
        if os.getppid() != parent_pid:  # the parent died before prctl: follow it now
            os._exit(128 + signal.SIGKILL)
        if max_memory:
            resource.setrlimit(resource.RLIMIT_AS, (max_memory, max_memory))
    return setup


def _threads_here():
    """The cores of this machine (its CPU affinity: a Slurm or cgroup allocation) shared among the
    parts a Dask worker runs at once."""
    cores = len(os.sched_getaffinity(0))
    slots = 1
    try:
        import distributed
        worker = distributed.get_worker()
        slots = getattr(worker, "state", worker).nthreads  # Worker.state from distributed 2022.9
    except (ImportError, ValueError):  # not on a Dask worker
        pass
    return max(1, cores // slots)


def _dask_stop_poll(event_name):
    import distributed
    event = distributed.Event(event_name)
    return event.is_set


def _stop_child(proc):
    proc.terminate()
    try:
        proc.wait(TERMINATE_GRACE_SECONDS)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


def _read_log(log_path):
    try:
        return log_path.read_text(errors="replace")
    except OSError:
        return ""


def _reason(log, exit_code):
    """The child's last `meshprep: ...` line; for a child killed by a signal without one, the
    signal and its last words (an uncaught exception's what())."""
    lines = [line.strip() for line in log.splitlines() if line.strip()]
    reason = next((line for line in reversed(lines) if line.startswith("meshprep: ")), "")
    if not reason and exit_code < 0:
        reason = f"meshprep batch: the child was killed by {signal.Signals(-exit_code).name}"
        if lines:
            reason += f" ({lines[-1]})"
    return reason


def _dig(data, *keys):
    for key in keys:
        if not isinstance(data, dict) or key not in data:
            return None
        data = data[key]
    return data


def key_figures(report):
    """The figures batch.json copies from the part's report.json (None where it has none)."""
    tet_quality = _dig(report, "tets", "tet_quality") or {}
    return {
        "fem_ready": report.get("fem_ready"),
        "problems": report.get("problems") or [],
        "surface_faces": _dig(report, "quality", "faces"),
        "tets": tet_quality.get("tetrahedra"),
        "points": tet_quality.get("points"),
        "min_dihedral_deg": _dig(tet_quality, "min_dihedral_deg", "min"),
        "max_dihedral_deg": _dig(tet_quality, "max_dihedral_deg", "max"),
        "hausdorff_relative": _dig(report, "quality", "reference", "hausdorff_relative"),
        "tets_format": _dig(report, "tets", "format"),
        "stopped": report.get("stopped"),  # "time limit": the improvement ended there, with its best tets
    }


def publish(partial, final):
    """Renames the complete partial folder to OUT/PART, replacing an older OUT/PART: that one is
    first renamed aside (a hidden .PART.old-... folder, removed after), so OUT/PART is at every
    moment either the old complete folder, absent, or the new complete one."""
    for _ in range(3):  # another batch on the same OUT may publish the same part in between
        try:
            os.rename(partial, final)
            return
        except OSError as error:
            if error.errno not in (errno.ENOTEMPTY, errno.EEXIST):
                raise
        aside = final.with_name(f".{final.name}.old-{_owner_tag()}")
        try:
            os.rename(final, aside)
        except FileNotFoundError:
            continue
        try:
            os.rename(partial, final)
        finally:
            shutil.rmtree(aside, ignore_errors=True)
        return
    os.rename(partial, final)


def write_json_atomically(path, data):
    temporary = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    temporary.write_text(json.dumps(data, indent=2) + "\n")
    os.replace(temporary, path)


def _read_record(path):
    try:
        record = json.loads(Path(path).read_text())
        return record if isinstance(record, dict) else None
    except (OSError, ValueError):
        return None


def run_part(part, settings, should_stop=None):
    """Runs `meshprep pipeline` on one part and publishes OUT/PART (or skips a part done before).

    part: {"name", "input", "config"}; settings: {"out", "meshprep", "version", "flags", "threads"
    (None: share this machine's cores), "time_limit", "guard_seconds", "max_memory", "force",
    "dask_stop_event"}; should_stop: a callable polled while the child runs (local batches).
    Returns the part's batch.json record, with "skipped": True for a part done before, or
    {"part", "status": "interrupted", "discarded": True} when stopped before the child finished.
    """
    out, name = Path(settings["out"]), part["name"]
    final = out / name
    digest = _hash_if_readable(part, settings)  # unreadable: the child says why
    if digest and not settings["force"]:
        old = _read_record(final / "batch.json")
        # done before: ready or not (a part that ran out of memory may fit under a larger cap)
        if old and old.get("hash") == digest and old.get("exit_code") in (0, 1) and old.get("status") != "memory":
            return {**old, "skipped": True}
    if should_stop is None and settings.get("dask_stop_event"):
        should_stop = _dask_stop_poll(settings["dask_stop_event"])

    partial = out / f".{name}.partial-{_owner_tag()}"
    partial.mkdir()
    try:
        config_path = partial / "config.json"
        config_path.write_text(json.dumps(part["config"], indent=2) + "\n")
        threads = settings["threads"] or _threads_here()
        command = [settings["meshprep"], "pipeline", part["input"], "-o", str(partial), "--quiet",
                   "--config", str(config_path), "--threads", str(threads)]
        if settings["time_limit"]:
            command += ["--time-limit", f"{settings['time_limit']:g}"]
        command += settings["flags"]
        log_path = partial / "log.txt"
        start = time.monotonic()
        exit_code, stopped, guard_hit = _run_child(command, log_path, partial, settings, should_stop)
        seconds = time.monotonic() - start

        if stopped and exit_code not in (0, 1):  # unfinished: it reruns next time
            shutil.rmtree(partial, ignore_errors=True)
            return {"part": name, "status": "interrupted", "discarded": True}
        log = _read_log(log_path)
        reason = _reason(log, exit_code).replace(str(partial), str(final))
        if guard_hit:
            exit_code = 124
            reason = (f"meshprep batch: stopped after {seconds:.0f} s, over the part's wall-clock guard "
                      f"({GUARD_FACTOR:g} x --time-limit + {GUARD_MARGIN_SECONDS} s)")
        status = _status(exit_code, reason, log, settings["max_memory"])
        if exit_code not in (0, 1):  # nothing usable: keep the log and the config, not half-written files
            for entry in partial.iterdir():
                if entry.is_dir():
                    shutil.rmtree(entry)
                elif entry.name not in ("log.txt", "config.json"):
                    entry.unlink()
        report = _read_record(partial / "report.json") if exit_code in (0, 1) else None
        tets_files = sorted(p.name for p in partial.glob("tets.*"))
        record = {
            "part": name,
            "input": part["input"],
            "hash": digest,
            "exit_code": exit_code,
            "status": status,
            "reason": reason,
            "seconds": round(seconds, 3),
            "meshprep_version": settings["version"],
            "threads": threads,
            "flags": settings["flags"],
            "tets_file": tets_files[0] if tets_files else None,
            "figures": key_figures(report) if report else None,
            "finished": datetime.now(timezone.utc).isoformat(timespec="seconds"),
            "runner": f"{os.getpid()}@{socket.gethostname()}",
        }
        write_json_atomically(partial / "batch.json", record)
        publish(partial, final)
        return record
    except BaseException:
        shutil.rmtree(partial, ignore_errors=True)
        raise


def _run_child(command, log_path, partial, settings, should_stop):
    """Runs the child, its stdout and stderr into log_path; returns (exit code, stopped, guard hit).
    A negative exit code is the signal that killed it."""
    guard = settings["guard_seconds"]
    with open(log_path, "wb") as log:
        try:
            proc = subprocess.Popen(command, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                    preexec_fn=_child_setup(settings["max_memory"], os.getpid()))
        except OSError as error:  # e.g. exec refused under the memory cap
            log.write(f"meshprep: failed: cannot start {command[0]}: {error.strerror}\n".encode())
            return (3, False, False)
    start = last_beat = time.monotonic()
    while True:
        now = time.monotonic()
        wait = POLL_SECONDS if guard is None else max(0.0, min(POLL_SECONDS, start + guard - now))
        try:
            return (proc.wait(wait), False, False)
        except subprocess.TimeoutExpired:
            pass
        now = time.monotonic()
        if now - last_beat >= HEARTBEAT_SECONDS:
            os.utime(partial)  # this folder is alive: see STALE_AFTER_SECONDS
            last_beat = now
        if should_stop is not None and should_stop():
            _stop_child(proc)
            return (proc.returncode, True, False)
        if guard is not None and now - start >= guard:
            _stop_child(proc)
            return (proc.returncode, False, True)


def _status(exit_code, reason, log, max_memory):
    """The status word of a child's outcome. Out of memory: the child's verdict says so (TetGen out
    of memory is "not FEM-ready", exit 1), its log does (a failure), or it was killed by a signal
    while capped (an allocation failing under the cap aborts it)."""
    if exit_code == 1 and OUT_OF_MEMORY.search(reason):
        return "memory"
    if exit_code not in (0, 1, 2) and (OUT_OF_MEMORY.search(log) or (max_memory and exit_code < 0)):
        return "memory"
    if exit_code < 0:
        return "crashed"
    return EXIT_STATUS.get(exit_code, "failed")


def remove_stale_folders(out):
    """Removes the hidden folders of parts that are not being written any more: .PART.partial-...
    (a killed batch's unfinished part) and .PART.old-... (a replaced part caught mid-swap). A folder
    is stale when its owner process is dead on this host, or (any host) when it has not been
    touched for STALE_AFTER_SECONDS: a live owner touches it every HEARTBEAT_SECONDS."""
    host, now = socket.gethostname(), time.time()
    for entry in out.iterdir():
        match = PARTIAL_NAME.match(entry.name)
        if not match or not entry.is_dir():
            continue
        try:
            age = now - entry.stat().st_mtime
        except FileNotFoundError:
            continue
        owner_gone = match["host"] == host and not _process_alive(int(match["pid"]))
        if owner_gone or age > STALE_AFTER_SECONDS:
            shutil.rmtree(entry, ignore_errors=True)


def _process_alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


# ---------------------------------------------------------------------------------------------
# The summary: OUT/summary.csv, summary.json and index.html, from every OUT/*/batch.json

SUMMARY_COLUMNS = ("part", "status", "exit_code", "tets", "min_dihedral_deg", "max_dihedral_deg",
                   "hausdorff_relative", "stopped", "seconds", "reason", "input", "report")


class Summary:
    """Rebuilds the summary files of OUT. batch.json files already read are kept by their stat, so
    a rebuild reads only new ones; the files are rewritten atomically (temporary + rename), under a
    lock on OUT/.summary.lock so that shards sharing OUT do not interleave."""

    def __init__(self, out):
        self.out = out
        self._records = {}  # folder name -> (stat key, record)

    def rows(self):
        rows = []
        for entry in sorted(self.out.iterdir(), key=lambda e: e.name):
            if entry.name.startswith(".") or not entry.is_dir():
                continue
            try:
                stat = (entry / "batch.json").stat()
            except FileNotFoundError:
                continue
            key = (stat.st_ino, stat.st_mtime_ns, stat.st_size)
            cached = self._records.get(entry.name)
            if cached is None or cached[0] != key:
                record = _read_record(entry / "batch.json")
                if record is None:
                    continue
                cached = self._records[entry.name] = (key, record)
            rows.append(self._row(entry.name, cached[1]))
        return rows

    def _row(self, folder, record):
        figures = record.get("figures") or {}
        problems = figures.get("problems") or []
        has_report = (self.out / folder / "report.html").is_file()
        return {
            "part": folder,
            "status": record.get("status"),
            "exit_code": record.get("exit_code"),
            "tets": figures.get("tets"),
            "min_dihedral_deg": figures.get("min_dihedral_deg"),
            "max_dihedral_deg": figures.get("max_dihedral_deg"),
            "hausdorff_relative": figures.get("hausdorff_relative"),
            "stopped": figures.get("stopped"),
            "seconds": record.get("seconds"),
            # the verdict's reasons when the report has them, else the child's last message
            "reason": "; ".join(problems) if problems else record.get("reason", ""),
            "input": record.get("input"),
            "report": f"{folder}/report.html" if has_report else None,
        }

    def write(self):
        """Rewrites the three files; returns the summary (summary.json's content)."""
        with open(self.out / ".summary.lock", "a") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)
            rows = self.rows()
            summary = {"out": str(self.out), "updated": datetime.now(timezone.utc).isoformat(timespec="seconds"),
                       "counts": _count_statuses(rows), "parts": rows}
            self._write_csv(rows)
            write_json_atomically(self.out / "summary.json", summary)
            self._write_html(summary)
        return summary

    def _write_csv(self, rows):
        temporary = self.out / f".summary.csv.{os.getpid()}.tmp"
        with open(temporary, "w", newline="") as file:
            writer = csv.DictWriter(file, SUMMARY_COLUMNS)
            writer.writeheader()
            writer.writerows({k: ("" if v is None else v) for k, v in row.items()} for row in rows)
        os.replace(temporary, self.out / "summary.csv")

    def _write_html(self, summary):
        def number(value, digits):
            return "" if value is None else f"{value:.{digits}f}" if isinstance(value, float) else str(value)

        body = []
        for row in summary["parts"]:
            link = urllib.parse.quote(row["report"] or f"{row['part']}/log.txt")  # names may hold # ? or spaces
            hausdorff = row["hausdorff_relative"]
            body.append(
                f'<tr class="{html.escape(str(row["status"]))}"><td><a href="{html.escape(link)}">'
                f'{html.escape(row["part"])}</a></td><td>{html.escape(str(row["status"]))}</td>'
                f'<td>{row["exit_code"]}</td><td>{number(row["tets"], 0)}</td>'
                f'<td>{number(row["min_dihedral_deg"], 1)}</td><td>{number(row["max_dihedral_deg"], 1)}</td>'
                f'<td>{"" if hausdorff is None else f"{hausdorff:.2e}"}</td><td>{number(row["seconds"], 1)}</td>'
                f'<td class="reason">{html.escape(row["reason"] or "")}</td></tr>')
        counts = ", ".join(f"{n} {status}" for status, n in summary["counts"].items())
        page = f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>meshprep batch: {html.escape(self.out.name)}</title>
<style>
body {{ font: 14px sans-serif; margin: 1.5em; }}
table {{ border-collapse: collapse; }}
th, td {{ padding: 0.25em 0.6em; border-bottom: 1px solid #ddd; text-align: right; }}
td:first-child, td:nth-child(2), td.reason, th {{ text-align: left; }}
td.reason {{ max-width: 50em; font-size: 12px; }}
tr.ready td:nth-child(2) {{ color: #1a7f37; }}
tr.not-ready td:nth-child(2) {{ color: #9a6700; }}
tr:not(.ready):not(.not-ready) td:nth-child(2) {{ color: #cf222e; font-weight: bold; }}
</style></head><body>
<h1>meshprep batch: {html.escape(self.out.name)}</h1>
<p>{len(summary["parts"])} parts: {html.escape(counts)}. Updated {summary["updated"]}.
The part's name links to its report (or its log when it has none).</p>
<table><thead><tr><th>part</th><th>status</th><th>exit</th><th>tets</th><th>min dihedral (deg)</th>
<th>max dihedral (deg)</th><th>Hausdorff / bbox diagonal</th><th>seconds</th><th>reason</th></tr></thead>
<tbody>
{chr(10).join(body)}
</tbody></table></body></html>
"""
        temporary = self.out / f".index.html.{os.getpid()}.tmp"
        temporary.write_text(page)
        os.replace(temporary, self.out / "index.html")


def _count_statuses(rows):
    counts = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    return counts


# ---------------------------------------------------------------------------------------------
# Running the parts: locally (threads driving child processes) or on a Dask cluster


def run_local(parts, settings, jobs, on_done):
    """Runs the parts, `jobs` at a time, in the given order; on_done(record) in this thread."""
    stop = threading.Event()
    with concurrent.futures.ThreadPoolExecutor(jobs, thread_name_prefix="part") as pool:
        futures = {pool.submit(run_part, part, settings, stop.is_set): part for part in parts}
        try:
            for future in concurrent.futures.as_completed(futures):
                try:
                    record = future.result()
                except Exception as error:  # noqa: BLE001 (the driver failed on this part, e.g. disk full)
                    record = record_unfinished_part(futures[future], settings, "failed", error)
                on_done(record)
        except (KeyboardInterrupt, Stopped):
            stop.set()  # the running children are stopped within POLL_SECONDS
            for future in futures:
                future.cancel()
            _finish_after_stop(futures, on_done)
            raise


def _finish_after_stop(futures, on_done):
    """Waits for the parts still running after a stop; records those that finished anyway."""
    for future in futures:
        if future.cancelled():
            continue
        try:
            record = future.result()
        except Exception:  # noqa: BLE001 (stopping: the part reruns next time)
            continue
        if not record.get("discarded"):
            on_done(record)


def connect_to_dask(address):
    try:
        import distributed
    except ImportError:
        raise UsageError("--scheduler needs Dask's distributed module (apt-get install python3-distributed)") from None
    try:
        return distributed.Client(address, timeout="30s")
    except (OSError, TimeoutError) as error:
        raise UsageError(f"--scheduler {address}: cannot connect: {error}") from None


def run_on_dask(client, parts, settings, on_done):
    """Submits run_part for each part to the client's Dask scheduler; closes the client. Workers
    must see the inputs, OUT and the meshprep binary at the same paths. A part whose worker dies
    is run again by the scheduler (up to distributed.scheduler.allowed-failures times, then
    KilledWorker); one whose run_part raised is retried DASK_RETRIES times."""
    import distributed
    token = secrets.token_hex(4)
    stop_event = distributed.Event(f"meshprep-batch-stop-{token}", client=client)
    settings = {**settings, "dask_stop_event": f"meshprep-batch-stop-{token}"}
    # run_part is this module's (the __main__ block runs meshprep.batch.main): workers import it.
    futures = {}
    for rank, part in enumerate(parts):
        future = client.submit(run_part, part, settings, key=f"meshprep-part-{part['name']}-{token}",
                               priority=len(parts) - rank, retries=DASK_RETRIES, pure=False)
        futures[future] = part
    try:
        for future in distributed.as_completed(futures):
            try:
                record = future.result()
            except Exception as error:  # noqa: BLE001 (KilledWorker, or run_part raised every retry)
                record = record_unfinished_part(futures[future], settings, "crashed", error)
            on_done(record)
    except (KeyboardInterrupt, Stopped):
        stop_event.set()  # each running run_part polls it and stops its child
        running = {key for keys in client.processing().values() for key in keys}
        client.cancel([f for f in futures if f.key not in running])
        unfinished = [f for f in futures if f.key in running]
        distributed.wait(unfinished, timeout=TERMINATE_GRACE_SECONDS + 5 * POLL_SECONDS)
        _finish_after_stop([f for f in unfinished if f.status == "finished"], on_done)
        raise
    finally:
        client.close()


def record_unfinished_part(part, settings, status, error):
    """The batch.json of a part whose run_part never returned (its Dask workers kept dying, or the
    driver failed on it), published like any other so that the summary lists it; not exit 0 or
    1, so a rerun runs it again."""
    out, name = Path(settings["out"]), part["name"]
    record = {
        "part": name, "input": part["input"],
        "hash": _hash_if_readable(part, settings),
        "exit_code": None, "status": status,
        "reason": f"meshprep batch: the part did not finish: {type(error).__name__}: {error}",
        "seconds": None, "meshprep_version": settings["version"], "threads": settings["threads"],
        "flags": settings["flags"], "tets_file": None, "figures": None,
        "finished": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "runner": f"{os.getpid()}@{socket.gethostname()}",
    }
    partial = out / f".{name}.partial-{_owner_tag()}"
    partial.mkdir()
    write_json_atomically(partial / "batch.json", record)
    publish(partial, out / name)
    return record


# ---------------------------------------------------------------------------------------------
# Progress on stderr


class Progress:
    """One line per finished part: `[7/20] bracket: ready (12.3 s) · 1 failed · ETA 1m40s`."""

    def __init__(self, total, quiet):
        self.total, self.quiet = total, quiet
        self.done = self.ran = 0
        self.not_ready = self.failed = 0
        self.start = time.monotonic()

    def part_done(self, record):
        self.done += 1
        skipped = record.get("skipped", False)
        if not skipped:
            self.ran += 1
        if record["exit_code"] == 1:
            self.not_ready += 1
        elif record["exit_code"] != 0:
            self.failed += 1
        if self.quiet:
            return
        if skipped:
            what = f"skipped, {record['status']} before"
        else:
            what = f"{record['status']} ({record['seconds'] or 0:.1f} s)"
        line = f"[{self.done}/{self.total}] {record['part']}: {what}"
        if self.not_ready:
            line += f" · {self.not_ready} not ready"
        if self.failed:
            line += f" · {self.failed} failed"
        remaining = self.total - self.done
        if remaining and self.ran:
            # the parts left, at the pace of the parts that ran (skipped ones cost nothing)
            line += f" · ETA {_duration(remaining * (time.monotonic() - self.start) / self.ran)}"
        print(line, file=sys.stderr, flush=True)


def _duration(seconds):
    seconds = int(round(seconds))
    if seconds < 60:
        return f"{seconds}s"
    if seconds < 3600:
        return f"{seconds // 60}m{seconds % 60:02d}s"
    return f"{seconds // 3600}h{seconds // 60 % 60:02d}m"


# ---------------------------------------------------------------------------------------------
# The command line


class _Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(message)


def _parser():
    parser = _Parser(
        prog="meshprep batch", allow_abbrev=False,
        description="Run `meshprep pipeline` on many parts, each in its own process: locally, on a Dask "
                    "cluster or as one shard of a job array. OUT/PART holds each part's outputs once "
                    "complete; a rerun skips the parts done with the same input, configuration and "
                    "meshprep. OUT/summary.csv, summary.json and index.html list every part. Exit codes: "
                    "0 every part FEM-ready, 1 some part not ready or failed, 2 bad usage or inputs, "
                    "130 interrupted. docs/batch.md.",
        epilog="Flags after -- go to every `meshprep pipeline` run, e.g. -- --format inp --no-improve.")
    parser.add_argument("inputs", nargs="*", metavar="INPUT",
                        help="a folder (its .off .obj .ply .stl .xyz files, recursively), a glob pattern, or a "
                             "list file (.txt/.lst: one path per line, relative to the list, # comments)")
    parser.add_argument("-o", "--output", metavar="OUT", help="the output folder (required)")
    parser.add_argument("--config", metavar="FILE", help="configuration file (JSON) for every part")
    parser.add_argument("--overrides", metavar="FILE.csv",
                        help="per-part configuration: a `part` column (part name or input file name) and one "
                             "column per dotted key (simplify.ratio); a sidecar PART.json beside an input "
                             "file overrides its row")
    parser.add_argument("--jobs", type=int, metavar="N", help="parts at once (default: the cores)")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="run the parts on this Dask scheduler (tcp://host:8786) instead of locally")
    parser.add_argument("--shard", metavar="I/N", help="only the parts of shard I of N (parts sorted by name, "
                                                       "the k-th in shard k mod N + 1)")
    parser.add_argument("--max-memory", metavar="SIZE", help="address-space cap of each part (4G, 512M)")
    parser.add_argument("--time-limit", type=float, metavar="S",
                        help="time budget of each part (the pipeline's --time-limit); a part still running "
                             f"after {GUARD_FACTOR:g} x S + {GUARD_MARGIN_SECONDS} s is killed (exit 124)")
    parser.add_argument("--threads", type=int, metavar="N",
                        help="threads of each part (default: the cores divided among the jobs)")
    parser.add_argument("--force", action="store_true", help="rerun the parts done before too")
    parser.add_argument("--json", metavar="FILE", help="write the summary as JSON to FILE ('-' = stdout)")
    parser.add_argument("--quiet", action="store_true", help="no progress lines")
    parser.add_argument("--meshprep", metavar="PATH",
                        help="the meshprep binary (default: $MESHPREP_BIN, else meshprep on PATH)")
    return parser


def _find_binary(option):
    candidate = option or os.environ.get("MESHPREP_BIN") or shutil.which("meshprep")
    if not candidate:
        raise UsageError("cannot find the meshprep binary: give --meshprep PATH or set MESHPREP_BIN")
    try:
        run = subprocess.run([candidate, "--version"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise UsageError(f"{candidate}: cannot run: {error}") from None
    if run.returncode != 0 or not run.stdout.startswith("meshprep "):
        raise UsageError(f"{candidate}: `--version` did not print `meshprep X.Y.Z`")
    return str(Path(candidate).resolve()), run.stdout.strip()


def _check_configuration(binary, config, flags, where):
    """Lets the binary check the configuration and the pipeline flags once, before any part runs
    (`pipeline --print-config`), so that a typo fails the batch at once rather than every part."""
    with tempfile.TemporaryDirectory(prefix="meshprep-batch-") as directory:
        check = Path(directory, "config.json")
        check.write_text(json.dumps(config))
        run = subprocess.run([binary, "pipeline", "--config", str(check), *flags, "--print-config"],
                             capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        message = (run.stderr.strip().splitlines() or [f"exit {run.returncode}"])[-1]
        message = message.removeprefix("meshprep: error: ")
        if str(check) in message:
            message = message.replace(str(check), where)
        else:
            message = f"`meshprep pipeline {' '.join(flags)}`: {message}"
        raise UsageError(message)


def _parse(argv):
    """The parsed options, the pass-through flags after --."""
    argv = list(argv)
    flags = []
    if "--" in argv:
        cut = argv.index("--")
        argv, flags = argv[:cut], argv[cut + 1:]
    args = _parser().parse_args(argv)
    if not args.output:
        raise UsageError("-o OUT is required: the folder the parts are written into")
    if not args.inputs:
        raise UsageError("no input: give folders, glob patterns, list files or mesh files")
    for flag in flags:
        if flag.split("=", 1)[0] in FLAGS_THE_BATCH_SETS:
            raise UsageError(f"{flag} after --: the batch sets it (give --threads and --time-limit to the batch)")
    if args.jobs is not None and args.jobs < 1:
        raise UsageError(f"--jobs {args.jobs}: must be at least 1")
    if args.threads is not None and args.threads < 1:
        raise UsageError(f"--threads {args.threads}: must be at least 1")
    if args.time_limit is not None and not args.time_limit > 0:
        raise UsageError(f"--time-limit {args.time_limit:g}: must be positive")
    return args, flags


def main(argv=None):
    """The batch; returns its exit code."""
    argv = sys.argv[1:] if argv is None else argv
    in_main_thread = threading.current_thread() is threading.main_thread()
    if in_main_thread:  # else the caller handles signals
        handlers = {signum: signal.getsignal(signum) for signum in (signal.SIGINT, signal.SIGTERM)}
        signal.signal(signal.SIGTERM, _raise_stopped)
    try:
        return _main(argv)
    except UsageError as error:
        print(f"meshprep: error: {error}", file=sys.stderr)
        return 2
    except OSError as error:  # OUT's file system failed under the batch (full, gone)
        print(f"meshprep: failed: {error}", file=sys.stderr)
        return 3
    except Stopped as stop:
        return stop.code
    except KeyboardInterrupt:
        return 130
    finally:
        if in_main_thread:
            for signum, handler in handlers.items():
                signal.signal(signum, handler)


def _raise_stopped(signum, frame):
    raise Stopped(128 + signum)


def _ignore_stop_signals():
    """The batch's last writes (the summary) are not cut short by a second Ctrl-C."""
    if threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)
        signal.signal(signal.SIGTERM, signal.SIG_IGN)


def _main(argv):
    # 1. Everything that can be wrong with the command is found before OUT is touched.
    args, flags = _parse(argv)
    binary, version = _find_binary(args.meshprep)
    out = Path(args.output).resolve()
    if out.exists() and not out.is_dir():
        raise UsageError(f"{args.output}: exists and is not a folder")
    inputs = collect_inputs(args.inputs, out)
    if not inputs:
        raise UsageError("no mesh or point file (" + " ".join(MESH_SUFFIXES) + ") among the inputs")
    names = name_parts(inputs)
    input_of = {name: path for path, name in names.items()}
    all_names = sorted(input_of)
    selected = in_shard(all_names, parse_shard(args.shard)) if args.shard else all_names
    max_memory = parse_size(args.max_memory) if args.max_memory else None

    # 2. The configuration of each part: --config, then its --overrides row, then its sidecar.
    base = read_json_object(args.config, "the configuration") if args.config else {}
    overrides, override_keys, unmatched = (read_overrides(args.overrides, input_of) if args.overrides
                                           else ({}, [], []))
    parts = []
    for name in selected:
        config = merge(base, overrides.get(name, {}))
        sidecar = input_of[name].with_suffix(".json")
        if sidecar.is_file():
            config = merge(config, read_json_object(sidecar, "the part's sidecar configuration"))
        parts.append({"name": name, "input": str(input_of[name]), "config": config})
    check = base
    for key in override_keys:  # each column's key, with the first value in it
        value = next((v for v in (_get_dotted(c, key) for c in overrides.values()) if v is not None), None)
        if value is not None:
            check = merge(check, _dotted(key, value))
    time_flags = ["--time-limit", f"{args.time_limit:g}"] if args.time_limit else []
    _check_configuration(binary, check, flags + time_flags,
                         " + ".join(f for f in (args.config, args.overrides) if f) or "the configuration")
    client = connect_to_dask(args.scheduler) if args.scheduler else None  # the last check

    # 3. Run: the largest inputs first (the small ones then fill the gaps at the end).
    cores = len(os.sched_getaffinity(0))
    jobs = args.jobs or cores
    settings = {
        "out": str(out), "meshprep": binary, "version": version, "flags": flags,
        "threads": args.threads or (None if args.scheduler else max(1, cores // jobs)),
        "time_limit": args.time_limit,
        "guard_seconds": args.time_limit * GUARD_FACTOR + GUARD_MARGIN_SECONDS if args.time_limit else None,
        "max_memory": max_memory, "force": args.force, "dask_stop_event": None,
    }
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise UsageError(f"{args.output}: cannot create: {error.strerror}") from None
    remove_stale_folders(out)
    if not args.quiet:
        for who in unmatched:
            print(f"meshprep: warning: {args.overrides}: part {who} is not among the inputs", file=sys.stderr)
        where = f"on {args.scheduler}" if args.scheduler else (
            f"{jobs} at a time, {settings['threads']} thread{'s' if settings['threads'] > 1 else ''} each")
        shard = f" (shard {args.shard}, of {len(all_names)} in all)" if args.shard else ""
        print(f"meshprep batch: {len(parts)} parts{shard}, {where}, into {out}", file=sys.stderr, flush=True)

    summary = Summary(out)
    progress = Progress(len(parts), args.quiet)
    records = []

    def on_done(record):
        records.append(record)
        progress.part_done(record)
        summary.write()

    order = sorted(parts, key=lambda part: (-input_of[part["name"]].stat().st_size, part["name"]))
    stop_code = None
    try:
        if client:
            run_on_dask(client, order, settings, on_done)
        else:
            run_local(order, settings, jobs, on_done)
    except KeyboardInterrupt:
        stop_code = 130
    except Stopped as stop:
        stop_code = stop.code
    # Even when stopped: partials are gone, the summary lists what finished.
    _ignore_stop_signals()
    remove_stale_folders(out)
    final = summary.write()

    exit_code = stop_code or (0 if all(r["exit_code"] == 0 for r in records) else 1)
    if args.json:
        ran = [r["part"] for r in records if not r.get("skipped")]
        final["batch"] = {"parts": [p["name"] for p in parts], "ran": ran,
                          "skipped": [r["part"] for r in records if r.get("skipped")],
                          "shard": args.shard, "exit_code": exit_code}
        text = json.dumps(final, indent=2) + "\n"
        if args.json == "-":
            sys.stdout.write(text)
        else:
            Path(args.json).write_text(text)
    if not args.quiet:
        failed = [r["part"] for r in records if r["exit_code"] != 0]
        stopped = " (stopped)" if stop_code else ""
        print(f"meshprep batch: {len(records)} of {len(parts)} parts done{stopped}, "
              f"{len(records) - len(failed)} ready" + (f"; not ready or failed: {', '.join(failed)}" if failed else "")
              + f"; summary in {out / 'index.html'}", file=sys.stderr)
    return exit_code


def _dotted(dotted_key, value):
    config = {}
    set_dotted(config, dotted_key, value)
    return config


def _get_dotted(config, dotted_key):
    for key in dotted_key.split("."):
        if not isinstance(config, dict) or key not in config:
            return None
        config = config[key]
    return config


if __name__ == "__main__":
    # Run from the package module (not this __main__ copy), so that run_part is the importable
    # meshprep.batch.run_part on Dask workers too.
    from meshprep.batch import main as package_main
    sys.exit(package_main())
