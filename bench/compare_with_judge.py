#!/usr/bin/env python3
"""Cross-check `meshprep quality` against the independent CGAL yardstick in ../shared/tools/judge.

Usage: bench/compare_with_judge.py [--meshprep build/bin/meshprep] [--judge /tmp/judge-build/mesh-judge]
Build the judge first with its README (it needs libcgal-dev; meshprep itself never depends on it).
Prints one row per mesh and per reference pair, and exits 1 if any figure is out of the acceptance
bounds of issue #2: means and fractions within 0.5 %, Hausdorff within 3 %, topology flags equal.
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "..", "shared", "data", "meshes")
MESHES = ["bunny00.off", "fandisk.off", "femur.off", "blade.off", "turbine.off", "elephant.off",
          "ChineseDragon-10kv.off", "horizons.off", "three_peaks.off", "noisy/bunny_noisy.off",
          "noisy/fandisk_noisy.off", "decimated/bunny00_0.1_openmesh.off", "decimated/fandisk_0.3_cgal_gh.off"]
PAIRS = [("bunny00.off", "decimated/bunny00_0.1_openmesh.off"), ("fandisk.off", "decimated/fandisk_0.3_cgal_gh.off"),
         ("bunny00.off", "noisy/bunny_noisy.off"), ("fandisk.off", "noisy/fandisk_noisy.off")]


def run_json(cmd):
    return json.loads(subprocess.run(cmd, check=True, capture_output=True, text=True).stdout)


def rel(a, b):
    if a is None or b is None:
        return float("inf") if a != b else 0.0
    return abs(a - b) / max(abs(b), 1e-300) if b != 0 else abs(a)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--meshprep", default=os.path.join(ROOT, "build", "bin", "meshprep"))
    ap.add_argument("--judge", default="/tmp/judge-build/mesh-judge")
    args = ap.parse_args()
    if not os.path.isdir(DATA):
        print(f"skipped: {DATA} not found (../shared is not beside the clone)")
        return 0
    bad = []
    print(f"{'mesh':38} {'topology':8} {'SI m/j':>9} {'RR mean dev':>11} {'AR mean dev':>11} "
          f"{'minang dev':>10} {'<20 dev':>9} {'vol dev':>9}")
    for m in MESHES:
        path = os.path.join(DATA, m)
        mp = run_json([args.meshprep, "quality", path, "--json", "-"])
        jd = run_json([args.judge, "quality", path])
        topo_ok = all([mp["closed"] == jd["closed"], mp["manifold"] == jd["manifold"],
                       mp["oriented"] == jd["consistently_oriented"],
                       mp["components"] == jd["connected_components"],
                       mp["euler_characteristic"] == jd["euler_characteristic"],
                       mp["genus"] == jd["genus_total"], mp["border_edges"] == jd["border_edges"]])
        q = jd["quality"]
        devs = {"RR": rel(mp["radius_ratio"]["mean"], q["radius_ratio"]["mean"]),
                "AR": rel(mp["aspect_ratio"]["mean"], q["aspect_ratio"]["mean"]),
                "minang": rel(mp["min_angle_deg"]["mean"], q["min_angle_deg"]["mean"]),
                "<20": rel(mp["faces_min_angle_below_20"], q["frac_min_angle_lt_20"]),
                "vol": rel(abs(mp["volume"]) if mp["volume"] is not None else None, jd["volume"])}
        si_ok = mp["self_intersections"] == jd["self_intersecting_pairs"]
        print(f"{m:38} {'equal' if topo_ok else 'DIFFER':8} {mp['self_intersections']:>4}/{jd['self_intersecting_pairs']:<4} "
              f"{devs['RR']:>11.2e} {devs['AR']:>11.2e} {devs['minang']:>10.2e} {devs['<20']:>9.2e} {devs['vol']:>9.2e}")
        if not topo_ok or not si_ok or max(devs.values()) > 0.005:
            bad.append(m)
    print()
    print(f"{'reference -> mesh':60} {'Hausdorff rel m/j':>22} {'dev':>8} {'RMS dev':>8} {'mean dev':>8}")
    for ref, m in PAIRS:
        rp, mpth = os.path.join(DATA, ref), os.path.join(DATA, m)
        mp = run_json([args.meshprep, "quality", mpth, "--reference", rp, "--json", "-"])["reference"]
        jd = run_json([args.judge, "compare", rp, mpth, "--threads", "2"])["distance"]
        jr = jd["relative_to_reference_bbox_diagonal"]
        dh = rel(mp["hausdorff_relative"], jr["hausdorff_symmetric"])
        dr = rel(mp["rms_relative"], jr["rms_symmetric"])
        dm = rel(mp["mean_relative"], jr["mean_symmetric"])
        print(f"{ref + ' -> ' + m:60} {mp['hausdorff_relative']:>10.4e}/{jr['hausdorff_symmetric']:<10.4e} "
              f"{dh:>8.2e} {dr:>8.2e} {dm:>8.2e}")
        if dh > 0.03 or dr > 0.005 or dm > 0.005:
            bad.append(f"{ref} -> {m}")
    print()
    print("all within bounds" if not bad else "OUT OF BOUNDS: " + ", ".join(bad))
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
