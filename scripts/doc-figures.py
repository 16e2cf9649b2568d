#!/usr/bin/env python3
"""The figures the README and docs quote from the bundled examples, from the runs themselves.

A quoted figure is marked in the Markdown source by an HTML comment before it (invisible once
rendered): `<!--fig:femur.min_dihedral-->15.0`. The number after the marker is the figure at the
precision quoted (its decimals, or its mantissa's in e-notation; thousands separators allowed).

Usage:
  doc-figures.py OUTDIR                  print every figure of OUTDIR/<example>/report.json
  doc-figures.py OUTDIR --check FILE...  exit 1, naming each, if a marked figure differs from the run
  doc-figures.py OUTDIR --update FILE... rewrite each marked figure from the run, at its precision
  doc-figures.py OUTDIR --picture NAME PNG
                                         the top of OUTDIR/NAME/report.html as the PNG (headless
                                         Chromium, 1200 x 1500): the README's docs/report.png is
                                         `--picture femur docs/report.png`
OUTDIR holds one folder per example, as scripts/run-example.sh writes them (out/); the examples
are listed in examples/pipeline_examples.txt.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

MARKER = re.compile(r"<!--fig:([a-z0-9_.]+)-->([0-9][0-9,]*(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?)")


def figures(outdir):
    """Every figure, by name: <example>.<figure>."""
    found = {}
    for name in sorted(os.listdir(outdir)):
        path = os.path.join(outdir, name, "report.json")
        if not os.path.isfile(path):
            continue
        with open(path) as f:
            r = json.load(f)
        tets = r["tets"]
        final = tets["tet_quality"]
        tetgen = tets["tetgen_quality"] or final  # no improvement ran: the tets are TetGen's
        stages = {s["name"]: s for s in r["stages"]}
        fig = {
            "input_faces": r["input_quality"]["faces"],
            "faces": r["quality"]["faces"],
            "input_faces_below_20": 100 * r["input_quality"]["faces_min_angle_below_20"],
            "faces_below_20": 100 * r["quality"]["faces_min_angle_below_20"],
            "input_min_angle": r["input_quality"]["min_angle_deg"]["min"],
            "min_angle": r["quality"]["min_angle_deg"]["min"],
            "radius_ratio_p95": r["quality"]["radius_ratio"]["p95"],
            "hausdorff": stages["quality"]["hausdorff_relative"],
            "fem_ready": 1 if r["fem_ready"] else 0,
        }
        if final:
            fig.update({
                "tets": final["tetrahedra"],
                "tets_k": final["tetrahedra"] / 1000,
                "tetgen_min_dihedral": tetgen["min_dihedral_deg"]["min"],
                "tetgen_max_dihedral": tetgen["max_dihedral_deg"]["max"],
                "min_dihedral": final["min_dihedral_deg"]["min"],
                "max_dihedral": final["max_dihedral_deg"]["max"],
            })
        for key, value in fig.items():
            found[f"{name}.{key}"] = value
    return found


def formatted(value, quoted):
    """`value` at the precision of the string `quoted`."""
    plain = quoted.replace(",", "")
    if "e" in plain:
        mantissa = plain.split("e")[0]
        decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
        text = f"{value:.{decimals}e}"
        base, exponent = text.split("e")
        return f"{base}e{int(exponent)}"
    decimals = len(plain.split(".")[1]) if "." in plain else 0
    text = f"{value:.{decimals}f}"
    if "," in quoted:  # thousands separators, as quoted
        whole, _, fraction = text.partition(".")
        text = f"{int(whole):,}" + ("." + fraction if fraction else "")
    return text


def picture(outdir, name, png):
    """Renders OUTDIR/NAME/report.html's top into `png` with headless Chromium."""
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        print("doc-figures: Chromium is not installed (scripts/install-deps.sh installs it)", file=sys.stderr)
        return 2
    page = os.path.abspath(os.path.join(outdir, name, "report.html"))
    with tempfile.TemporaryDirectory() as work:
        shot = os.path.join(work, "report.png")
        subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                        "--window-size=1200,1500", f"--screenshot={shot}", "file://" + page],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=120, check=False)
        if not os.path.isfile(shot) or os.path.getsize(shot) == 0:
            print(f"doc-figures: Chromium made no picture of {page}", file=sys.stderr)
            return 1
        shutil.copyfile(shot, png)
    print(f"doc-figures: {png} is {page} as Chromium shows it")
    return 0


def main(argv):
    if len(argv) < 2 or argv[1] in ("-h", "--help"):
        print(__doc__)
        return 0 if len(argv) > 1 else 2
    known = figures(argv[1])
    if not known:
        print(f"doc-figures: no example's report.json under {argv[1]}", file=sys.stderr)
        return 2
    if len(argv) == 2:
        for key, value in known.items():
            print(f"{key} = {value}")
        return 0
    mode, files = argv[2], argv[3:]
    if mode == "--picture" and len(files) == 2:
        return picture(argv[1], files[0], files[1])
    if mode not in ("--check", "--update") or not files:
        print(__doc__, file=sys.stderr)
        return 2
    stale, marked = [], 0
    for path in files:
        with open(path) as f:
            text = f.read()

        def replace(match):
            nonlocal marked
            key, quoted = match.group(1), match.group(2)
            marked += 1
            if key not in known:
                stale.append(f"{path}: {key}: no such figure (known: {', '.join(sorted(known))})")
                return match.group(0)
            now = formatted(known[key], quoted)
            if now != quoted:
                stale.append(f"{path}: {key}: quoted {quoted}, the run gives {now}")
            return f"<!--fig:{key}-->{now}"

        updated = MARKER.sub(replace, text)
        if mode == "--update" and updated != text:
            with open(path, "w") as f:
                f.write(updated)
    if marked == 0:
        print("doc-figures: no marked figure in " + " ".join(files), file=sys.stderr)
        return 1
    if mode == "--check" and stale:
        print("\n".join(stale))
        print(f"doc-figures: {len(stale)} of {marked} quoted figures differ from the run; "
              "scripts/doc-figures.py OUTDIR --update FILE... rewrites them")
        return 1
    print(f"doc-figures: {marked} quoted figures {'checked' if mode == '--check' else 'current'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
