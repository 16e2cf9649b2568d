#!/usr/bin/env python3
"""Helper of bench/bench_repair_suite.sh: the Markdown table of the repair suite (issue 48, item 5).

Usage: repair_suite_table.py RESULTS.tsv RUNS_DIR [--timeout S]

  RESULTS.tsv  one row per case, tab-separated, with a header: name, kind, exit, seconds, faces
  RUNS_DIR     where the bench left NAME.err (meshprep's stderr) and NAME.json (its --json summary)
  --timeout S  the time limit the runs had: an exit of 124 or 137 (timeout's kill) after at least
               S seconds counts as 'hang'

Prints, per defect kind and in total: cases, FEM-ready (exit 0) count and share, the histogram of
exit codes ("0:8 1:1 hang:1"), 'surface ok' (the summary's final surface is closed, manifold and
free of self-intersections, whatever the tets' verdict), median and worst wall seconds. Below the
table, one line per case that did not exit 0: its exit and the first line of its stderr (the named
reason), the case's file path shortened to its name. Exit codes of meshprep: 0 ready, 1 written
but not ready, 2 bad input (nothing written), 3 failed while working, 124 time limit, 130
interrupted; above 128 otherwise: killed by a signal (128 + its number).
"""
import csv
import json
import os
import signal
import statistics
import sys


def first_line(path):
    try:
        with open(path, errors="replace") as f:
            for line in f:
                if line.strip():
                    return line.strip()
    except OSError:
        pass
    return ""


def summary(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def surface_ok(report):
    q = (report or {}).get("quality") or {}
    return bool(q.get("closed")) and bool(q.get("manifold")) and q.get("self_intersections") == 0


def code(row, timeout):
    rc = int(row["exit"])
    if rc in (124, 137) and timeout and float(row["seconds"]) >= timeout:
        return "hang"
    return str(rc)


def reason(row, runs, timeout):
    c = code(row, timeout)
    if c == "hang":
        return "hang: killed by timeout after %.0f s" % float(row["seconds"])
    text = first_line(os.path.join(runs, row["name"] + ".err"))
    for prefix in (row.get("path", ""),):
        if prefix:
            text = text.replace(prefix, os.path.basename(prefix))
    rc = int(row["exit"])
    if not text and rc > 128 and rc not in (130,):
        try:
            text = "(no stderr) killed by %s" % signal.Signals(rc - 128).name
        except ValueError:
            text = "(no stderr)"
    if len(text) > 240:
        text = text[:237] + "..."
    return text or "(no stderr)"


def histogram(codes):
    order = lambda c: (c == "hang", int(c) if c.isdigit() else 1000)
    counts = {}
    for c in codes:
        counts[c] = counts.get(c, 0) + 1
    return " ".join("%s:%d" % (c, counts[c]) for c in sorted(counts, key=order))


def line(label, rows, runs, timeout):
    codes = [code(r, timeout) for r in rows]
    ready = codes.count("0")
    ok = sum(surface_ok(summary(os.path.join(runs, r["name"] + ".json"))) for r in rows)
    secs = [float(r["seconds"]) for r in rows]
    return "| %s | %d | %d | %.0f %% | %s | %d | %.1f | %.1f |" % (
        label, len(rows), ready, 100.0 * ready / len(rows), histogram(codes), ok,
        statistics.median(secs), max(secs))


def main():
    args = sys.argv[1:]
    timeout = None
    if "--timeout" in args:
        i = args.index("--timeout")
        timeout = float(args[i + 1])
        del args[i:i + 2]
    if len(args) != 2:
        sys.exit(__doc__.split("\n\n", 1)[1].split("\n\n", 1)[0])
    tsv, runs = args
    with open(tsv, newline="") as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    if not rows:
        sys.exit("repair_suite_table.py: no runs in " + tsv)
    kinds = []
    for r in rows:
        if r["kind"] not in kinds:
            kinds.append(r["kind"])
    print("| defect | cases | FEM-ready | % | exit codes | surface ok | median s | worst s |")
    print("| --- | ---: | ---: | ---: | --- | ---: | ---: | ---: |")
    for kind in kinds:
        print(line(kind, [r for r in rows if r["kind"] == kind], runs, timeout))
    print(line("**total**", rows, runs, timeout))
    failed = [r for r in rows if r["exit"] != "0"]
    if failed:
        print()
        print("Not FEM-ready (exit, wall seconds, first line of stderr):")
        print()
        for r in failed:
            print("- `%s`: %s, %.1f s: %s" % (r["name"], code(r, timeout), float(r["seconds"]),
                                              reason(r, runs, timeout)))


if __name__ == "__main__":
    main()
