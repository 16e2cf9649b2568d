#!/usr/bin/env python3
"""Helper of bench/bench_corpus.sh (issue 32's corpus bench). Three subcommands:

  corpus_table.py noise CLEAN.off OUT.off SIGMA SEED
      OUT = CLEAN with every vertex moved along its area-weighted normal by a Gaussian of standard
      deviation SIGMA x the bounding-box diagonal (numpy, seeded: the same SEED gives the same file).
  corpus_table.py row DIR SET MESH       one CSV row (no header) from the files the bench left in DIR
  corpus_table.py header                 the CSV header
  corpus_table.py table CSV              the Markdown table: median and worst of each figure per set

Figures are fractions or plain numbers in the CSV; the table prints percentages where the figure
is a share. Hausdorff and RMS are relative to the reference's bounding-box diagonal.
"""
import csv
import json
import os
import re
import statistics
import sys

FIELDS = [
    "set", "mesh", "faces", "closed", "self_intersections", "below20_in", "rr95_in",
    "enh_exit", "enh_faces", "enh_below20", "enh_rr95", "enh_hausdorff", "enh_volume_pct", "enh_time",
    "enh_self_intersections",
    "cgal_exit", "cgal_faces", "cgal_time", "cgal_below20", "cgal_rr95", "cgal_hausdorff", "cgal_volume_pct",
    "pipe_exit", "pipe_refused", "pipe_error", "fem_ready", "pipe_faces", "pipe_below20", "pipe_rr95",
    "pipe_hausdorff", "pipe_volume_pct", "pipe_self_intersections", "tet_min_dihedral", "pipe_time",
    "smoothed",
    "noisy1_rms", "rbf1_exit", "rbf1_rms", "taubin1_exit", "taubin1_rms",
    "noisy2_rms", "rbf2_exit", "rbf2_rms", "taubin2_exit", "taubin2_rms",
]


# ---------------------------------------------------------------------------------------------
# noise
def read_off(path):
    lines = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line:
                lines.append(line)
    head = lines[0].split()
    if not head[0].endswith("OFF"):
        raise SystemExit("%s: not an OFF file" % path)
    rest = head[1:]
    i = 1
    if not rest:
        rest = lines[1].split()
        i = 2
    nv, nf = int(rest[0]), int(rest[1])
    import numpy as np
    vertices = np.array([[float(x) for x in lines[i + k].split()[:3]] for k in range(nv)])
    faces = []
    for k in range(nf):
        t = lines[i + nv + k].split()
        n = int(t[0])
        idx = [int(x) for x in t[1:1 + n]]
        faces.extend([idx[0], idx[j], idx[j + 1]] for j in range(1, n - 1))  # fan: OFF polygons
    return vertices, np.array(faces, dtype=np.int64)


def noise(clean, out, sigma, seed):
    import numpy as np
    v, f = read_off(clean)
    n = np.zeros_like(v)
    a, b, c = v[f[:, 0]], v[f[:, 1]], v[f[:, 2]]
    fn = np.cross(b - a, c - a)  # length = twice the area: the sum is area-weighted
    for k in range(3):
        np.add.at(n, f[:, k], fn)
    length = np.linalg.norm(n, axis=1)
    length[length == 0] = 1
    n /= length[:, None]
    diagonal = float(np.linalg.norm(v.max(axis=0) - v.min(axis=0)))
    rng = np.random.default_rng(seed)
    v = v + n * rng.normal(0.0, sigma * diagonal, size=len(v))[:, None]
    with open(out, "w") as o:
        o.write("OFF\n%d %d 0\n" % (len(v), len(f)))
        o.writelines("%.17g %.17g %.17g\n" % tuple(p) for p in v)
        o.writelines("3 %d %d %d\n" % tuple(t) for t in f)


# ---------------------------------------------------------------------------------------------
# row
def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def text(path):
    try:
        with open(path) as f:
            return f.read().strip()
    except OSError:
        return ""


def surface(q, prefix, row):
    """The figures of a surface quality report q (with its reference section)."""
    if not q:
        return
    row[prefix + "faces"] = q["faces"]
    row[prefix + "below20"] = q["faces_min_angle_below_20"]
    row[prefix + "rr95"] = q["radius_ratio"]["p95"]
    r = q.get("reference") or {}
    row[prefix + "hausdorff"] = r.get("hausdorff_relative")
    row[prefix + "volume_pct"] = r.get("volume_change_percent")
    if prefix + "self_intersections" in FIELDS:
        row[prefix + "self_intersections"] = q["self_intersections"]


def row(d, set_name, mesh):
    r = {"set": set_name, "mesh": mesh}
    q = load(os.path.join(d, "q.json"))
    if q:
        r.update(faces=q["faces"], closed=int(q["closed"]), self_intersections=q["self_intersections"],
                 below20_in=q["faces_min_angle_below_20"], rr95_in=q["radius_ratio"]["p95"])
    r["enh_exit"] = text(os.path.join(d, "e.rc"))
    e = load(os.path.join(d, "e.json"))
    if e and r["enh_exit"] == "0":
        surface(e["quality"], "enh_", r)
        r["enh_time"] = e["time_seconds"]
    r["cgal_exit"] = text(os.path.join(d, "c.rc"))
    if r["cgal_exit"] == "0":
        c = text(os.path.join(d, "c.txt")).split()
        r["cgal_time"] = float(c[0])
        surface(load(os.path.join(d, "cq.json")), "cgal_", r)
    r["pipe_exit"] = text(os.path.join(d, "p.rc"))
    p = load(os.path.join(d, "p.json"))
    tets = (p or {}).get("tets") or {}
    if r["pipe_exit"]:
        r["pipe_refused"] = int(r["pipe_exit"] != "0" and not tets.get("tet_quality"))
        if r["pipe_exit"] != "0":
            lines = [l for l in text(os.path.join(d, "p.err")).splitlines() if l.strip()]
            # the first error line, its paths cut to file names
            r["pipe_error"] = re.sub(r"\S*/", "", lines[0]).replace("meshprep: ", "", 1)[:160] if lines else ""
    if p:
        r["fem_ready"] = int(bool(p.get("fem_ready")))
        surface(p.get("quality"), "pipe_", r)
        r["pipe_time"] = p.get("time_seconds")
        if tets.get("tet_quality"):
            r["tet_min_dihedral"] = tets["tet_quality"]["min_dihedral_deg"]["min"]
    r["smoothed"] = int(os.path.exists(os.path.join(d, "s1_noisy.json")))
    for s in (1, 2):
        for kind in ("noisy", "rbf", "taubin"):
            if kind != "noisy":
                r["%s%d_exit" % (kind, s)] = text(os.path.join(d, "s%d_%s.rc" % (s, kind)))
            j = load(os.path.join(d, "s%d_%s.json" % (s, kind)))
            if j and (kind == "noisy" or r["%s%d_exit" % (kind, s)] == "0"):
                r["%s%d_rms" % (kind, s)] = j["reference"]["rms_relative"]
    w = csv.DictWriter(sys.stdout, FIELDS, lineterminator="\n")
    w.writerow(r)


# ---------------------------------------------------------------------------------------------
# table
def num(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def fmt(x, kind):
    if x is None:
        return "–"
    if kind == "pct":
        return "%.1f %%" % (100 * x)
    if kind == "pct2":  # already a percentage
        return "%.3g %%" % x
    if kind == "int":
        return "%d" % round(x)
    if kind == "s":
        return "%.2g s" % x if x < 10 else "%.0f s" % x
    if kind == "deg":
        return "%.1f°" % x
    if kind == "x":
        return "%.2f" % x
    return "%.2g" % x


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    sets = [s for s in ("cad", "corpus", "meshes") if any(r["set"] == s for r in rows)]

    def col(r, name):
        return num(r.get(name))

    def ratio(a, b):
        return lambda r: (col(r, a) / col(r, b)) if col(r, a) is not None and col(r, b) else None

    def absolute(name):
        return lambda r: abs(col(r, name)) if col(r, name) is not None else None

    def plain(name):
        return lambda r: col(r, name)

    # (label, value function, format, worst = max or min)
    figures = [
        ("**input**", None, None, None),
        ("faces", plain("faces"), "int", max),
        ("faces min angle < 20°", plain("below20_in"), "pct", max),
        ("radius ratio p95", plain("rr95_in"), "x", max),
        ("self-intersecting face pairs", plain("self_intersections"), "int", max),
        ("**enhance** (defaults)", None, None, None),
        ("faces after / before", ratio("enh_faces", "faces"), "x", max),
        ("faces min angle < 20° (goal ≤ 1 %)", plain("enh_below20"), "pct", max),
        ("radius ratio p95 (goal ≤ 2)", plain("enh_rr95"), "x", max),
        ("Hausdorff / diagonal (goal ≤ 1e-3)", plain("enh_hausdorff"), "g", max),
        ("volume change (goal ≤ 0.1 %)", absolute("enh_volume_pct"), "pct2", max),
        ("time", plain("enh_time"), "s", max),
        ("**CGAL isotropic remeshing** (mean edge, 3 it.)", None, None, None),
        ("faces after / before", ratio("cgal_faces", "faces"), "x", max),
        ("faces min angle < 20°", plain("cgal_below20"), "pct", max),
        ("radius ratio p95", plain("cgal_rr95"), "x", max),
        ("Hausdorff / diagonal", plain("cgal_hausdorff"), "g", max),
        ("volume change", absolute("cgal_volume_pct"), "pct2", max),
        ("time", plain("cgal_time"), "s", max),
        ("enhance time / CGAL time (goal ≤ 2)", ratio("enh_time", "cgal_time"), "x", max),
        ("**pipeline** (defaults; final surface, tets)", None, None, None),
        ("faces min angle < 20°", plain("pipe_below20"), "pct", max),
        ("radius ratio p95", plain("pipe_rr95"), "x", max),
        ("Hausdorff / diagonal", plain("pipe_hausdorff"), "g", max),
        ("volume change", absolute("pipe_volume_pct"), "pct2", max),
        ("self-intersecting face pairs", plain("pipe_self_intersections"), "int", max),
        ("tets' smallest dihedral (goal ≥ 10°)", plain("tet_min_dihedral"), "deg", min),
        ("time", plain("pipe_time"), "s", max),
    ]
    for s, sigma in ((1, "0.1 %"), (2, "0.2 %")):
        figures += [
            ("**smooth**, noise σ = %s of the diagonal" % sigma, None, None, None),
            ("noisy input's RMS / diagonal", plain("noisy%d_rms" % s), "g", max),
            ("rbf RMS / noisy RMS (goal < 1)", ratio("rbf%d_rms" % s, "noisy%d_rms" % s), "x", max),
            ("taubin-10 RMS / noisy RMS", ratio("taubin%d_rms" % s, "noisy%d_rms" % s), "x", max),
            ("rbf RMS / taubin RMS (goal: median ≤ 0.9)", ratio("rbf%d_rms" % s, "taubin%d_rms" % s), "x", max),
        ]

    head = "| figure |" + "".join(" %s median | %s worst |" % (s, s) for s in sets)
    out = [head, "|" + " --- |" * (1 + 2 * len(sets))]

    def counts(label, fn):
        out.append("| %s |" % label + "".join(" %s | |" % fn([r for r in rows if r["set"] == s]) for s in sets))

    counts("meshes", len)
    counts("closed, no self-intersection", lambda rs: sum(r["closed"] == "1" and r["self_intersections"] == "0" for r in rs))
    counts("enhance failed (exit ≠ 0)", lambda rs: sum(r["enh_exit"] not in ("0", "") for r in rs))
    counts("CGAL peer ran", lambda rs: sum(r["cgal_exit"] == "0" for r in rs))
    counts("pipeline refused (exit 1/2, no tets)",
           lambda rs: sum(r["pipe_refused"] == "1" and "timed out" not in r["pipe_error"] for r in rs))
    counts("pipeline timed out (PIPELINE_TIMEOUT)", lambda rs: sum("timed out" in r["pipe_error"] for r in rs))
    counts("pipeline fem_ready", lambda rs: "%d / %d" % (sum(r["fem_ready"] == "1" for r in rs), len(rs)))
    for label, fn, kind, worst in figures:
        if fn is None:
            out.append("| %s |" % label + " |" * (2 * len(sets)))
            continue
        cells = []
        for s in sets:
            vals = [(fn(r), r["mesh"]) for r in rows if r["set"] == s]
            vals = [(v, m) for v, m in vals if v is not None]
            if not vals:
                cells += ["–", "–"]
                continue
            med = statistics.median(v for v, _ in vals)
            w = worst(vals, key=lambda t: t[0])
            cells += [fmt(med, kind), "%s (%s)" % (fmt(w[0], kind), os.path.splitext(w[1])[0])]
        out.append("| %s | %s |" % (label, " | ".join(cells)))
    # smoothing: shares of meshes
    for s, sigma in ((1, "0.1 %"), (2, "0.2 %")):
        parts = []
        for st in sets:
            rs = [r for r in rows if r["set"] == st and num(r.get("rbf%d_rms" % s)) is not None]
            if not rs:
                parts.append(" – | |")
                continue
            noisy = sum(num(r["rbf%d_rms" % s]) < num(r["noisy%d_rms" % s]) for r in rs)
            both = [r for r in rs if num(r.get("taubin%d_rms" % s))]  # Taubin may refuse (self-intersections)
            taubin = sum(num(r["rbf%d_rms" % s]) < num(r["taubin%d_rms" % s]) for r in both)
            gains = [1 - num(r["rbf%d_rms" % s]) / num(r["taubin%d_rms" % s]) for r in both]
            parts.append(" below noisy %d / %d; below Taubin %d / %d (goal ≥ 90 %%; Taubin refused on %d more); median gain over Taubin %s (goal ≥ 10 %%) | |"
                         % (noisy, len(rs), taubin, len(both), len(rs) - len(both),
                            fmt(statistics.median(gains), "pct") if gains else "–"))
        out.append("| smooth σ = %s: rbf beats |" % sigma + "".join(parts))
    print("\n".join(out))


def main():
    cmd = sys.argv[1] if len(sys.argv) > 1 else ""
    if cmd == "noise" and len(sys.argv) == 6:
        noise(sys.argv[2], sys.argv[3], float(sys.argv[4]), int(sys.argv[5]))
    elif cmd == "row" and len(sys.argv) == 5:
        row(*sys.argv[2:5])
    elif cmd == "header":
        print(",".join(FIELDS))
    elif cmd == "table" and len(sys.argv) == 3:
        table(sys.argv[2])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main()
