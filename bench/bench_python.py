"""The Python module's costs (issue 46), each measured side by side in one run, alternating, medians of 5:

1. quality(): the whole process `python3 -c "meshprep.quality(meshprep.read(F))"` against
   `meshprep quality F --json FILE` (both read the file, measure and make the JSON);
2. a surface's round trip numpy -> meshprep.Surface -> numpy views, beyond the one copy it needs
   (numpy's own copy of the same arrays);
3. two threads calling simplify() on two meshes at once, against the two calls one after the other;
4. how long Ctrl-C (SIGINT) takes to stop improve() on a large tet mesh.

Usage: PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [build-dir]
Needs ../shared/data/meshes (bunny00.off); prints a Markdown table."""

import os
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
BUILD = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build"
DATA = ROOT.parent / "shared" / "data" / "meshes"
sys.path.insert(0, str(BUILD / "python"))
import meshprep  # noqa: E402

RUNS = 5


def wall(fn):
    start = time.perf_counter()
    fn()
    return time.perf_counter() - start


def alternate(a, b):
    """Medians of a's and b's times and of the ratio a/b, pair by pair (one warm-up each)."""
    a(), b()
    pairs = [(wall(a), wall(b)) for _ in range(RUNS)]
    return (statistics.median(p[0] for p in pairs), statistics.median(p[1] for p in pairs),
            statistics.median(p[0] / p[1] for p in pairs))


def main():
    if not DATA.is_dir():
        print(f"skipped: {DATA} not found")
        return 0
    work = Path(tempfile.mkdtemp())
    big = work / "bunny_l2.off"  # bunny00 Loop-subdivided twice: 1.2 M faces
    subprocess.run([BUILD / "bin" / "subdivide_mesh", DATA / "bunny00.off", big, "2"], check=True,
                   stdout=subprocess.DEVNULL)
    env = dict(os.environ, PYTHONPATH=str(BUILD / "python"))
    rows = []

    # 1. quality(): whole processes.
    python = [sys.executable, "-c", f"import meshprep; meshprep.quality(meshprep.read({str(big)!r}))"]
    cli = [BUILD / "bin" / "meshprep", "quality", big, "--json", work / "q.json"]
    t_py, t_cli, ratio = alternate(lambda: subprocess.run(python, check=True, env=env),
                                   lambda: subprocess.run(cli, check=True, stdout=subprocess.DEVNULL))
    rows.append(("quality, 1.2 M faces, whole process: Python / CLI", f"{t_py:.2f} s / {t_cli:.2f} s",
                 f"**{ratio:.3f}x** (goal <= 1.1x)"))

    # 2. round trip beyond the copy.
    surface = meshprep.read(big)
    points, faces = surface.points.copy(), surface.faces.astype(np.int64)

    def round_trip():
        s = meshprep.Surface(points, faces)
        return np.asarray(s.points), np.asarray(s.faces)

    def copy_only():
        return points.copy(), faces.astype(np.uint32)

    t_trip, t_copy, _ = alternate(round_trip, copy_only)
    rows.append((f"round trip numpy -> Surface -> numpy, {len(faces) / 1e6:.2f} M faces, beyond numpy's copy",
                 f"{t_trip * 1e3:.1f} ms - {t_copy * 1e3:.1f} ms", f"**{(t_trip - t_copy) * 1e3:.1f} ms** (goal <= 50 ms)"))

    # 3. two threads of simplify, on two meshes of the same size (bunny00 read twice), so that
    # neither thread waits for the other at the end.
    first, second = meshprep.read(DATA / "bunny00.off"), meshprep.read(DATA / "bunny00.off")

    call_threads = [0]

    def one(mesh):
        meshprep.simplify(mesh, ratio=0.2, quality={"distance_samples": 100000}, threads=call_threads[0])

    def serial():
        one(first), one(second)

    def parallel():
        threads = [threading.Thread(target=one, args=(m,)) for m in (first, second)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()

    t_par, t_ser, ratio = alternate(parallel, serial)
    rows.append(("simplify two bunny00 (75 k faces) to 20 % in two threads / one after the other", f"{t_par:.2f} s / {t_ser:.2f} s",
                 f"**{ratio:.3f}x** (goal <= 0.6x)"))
    call_threads[0] = 1  # each call on one thread (threads=1): the threads' own parallelism alone
    t_par, t_ser, ratio = alternate(parallel, serial)
    rows.append(("the same, each call threads=1", f"{t_par:.2f} s / {t_ser:.2f} s", f"**{ratio:.3f}x** (goal <= 0.6x)"))

    # 4. Ctrl-C during improve().
    tets = meshprep.tetrahedralize(meshprep.read(DATA / "bunny00.off"), max_volume_relative=1e-6, improve=False,
                                   verdict={"min_dihedral_deg": 0, "max_dihedral_deg": 180}).tets
    latencies = []
    for _ in range(RUNS):
        sent = []
        timer = threading.Timer(1.0, lambda: (sent.append(time.perf_counter()), os.kill(os.getpid(), signal.SIGINT)))
        timer.start()
        try:
            meshprep.improve(tets, goal_min_dihedral_deg=59, max_passes=1000)
        except KeyboardInterrupt:
            latencies.append(time.perf_counter() - sent[0])
        timer.join()
    rows.append((f"Ctrl-C during improve() of {len(tets.tets)} tets: SIGINT to KeyboardInterrupt",
                 ", ".join(f"{x * 1e3:.0f}" for x in latencies) + " ms",
                 f"**{statistics.median(latencies) * 1e3:.0f} ms** median, {max(latencies) * 1e3:.0f} ms worst (goal <= 1 s)"))

    print("| what | times | figure |\n| --- | --- | --- |")
    for row in rows:
        print("| " + " | ".join(row) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
