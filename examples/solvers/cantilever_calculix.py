#!/usr/bin/env python3
"""A cantilever meshed by meshprep and solved by CalculiX, against Euler-Bernoulli.

Usage: cantilever_calculix.py [--meshprep BIN] [--order 1|2] [--work DIR] [--size LENGTH|NAME=LENGTH ...]

1. parts.py writes beam.obj, a 20 x 1 x 1 beam whose OBJ groups name its faces: fixed (x = 0),
   loaded (the top, y = 1), free (x = 20), bottom, sides.
2. `meshprep pipeline beam.obj -o DIR/mesh --format inp --config cantilever.json [--order 2]`
   writes DIR/mesh/tets.inp: C3D4 tets (C3D10 with --order 2), a node set and an element-face
   surface per patch, named as the groups. Each --size is passed on: `--size 0.25 --size fixed=0.05`
   asks for tets of 0.25 with 0.05 on the clamped end, graded between (docs/size_field.md).
3. `ccx -i cantilever` runs cantilever.inp, which includes tets.inp: clamped on "fixed", a pressure p
   on "loaded"; it prints the displacements of "free" into cantilever.dat.
4. The mean vertical displacement of the free end is compared with Euler-Bernoulli's tip deflection
   under a uniform load q = p W: q L^4 / (8 E I), I = W H^3 / 12. At L / H = 20 the shear
   deformation the beam theory leaves out is 4 E I / (kappa G A L^2) = 0.3 % of it.

Prints both deflections and their ratio. CalculiX is Debian's calculix-ccx.
"""
import argparse
import pathlib
import re
import shutil
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
LENGTH, HEIGHT, WIDTH = 20.0, 1.0, 1.0  # parts.py's beam
YOUNG_MODULUS, PRESSURE = 210000.0, 0.01  # cantilever.inp's


def euler_bernoulli_tip_deflection():
    q = PRESSURE * WIDTH
    inertia = WIDTH * HEIGHT**3 / 12
    return q * LENGTH**4 / (8 * YOUNG_MODULUS * inertia)


def printed_displacements(dat_path):
    """The rows 'node ux uy uz' of the .dat's displacement block."""
    rows, inside = [], False
    for line in open(dat_path):
        if line.strip().startswith("displacements"):
            inside = True
        elif inside and re.match(r"\s*\d+(\s+\S+){3}\s*$", line):
            rows.append([float(v) for v in line.split()[1:]])
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--meshprep", default=str(HERE.parents[1] / "build" / "bin" / "meshprep"))
    parser.add_argument("--order", type=int, choices=(1, 2), default=1)
    parser.add_argument("--work", default="cantilever")
    parser.add_argument("--size", action="append", default=[], help="passed on to meshprep pipeline --size")
    args = parser.parse_args()
    if shutil.which("ccx") is None:
        sys.exit("ccx is not on PATH (apt-get install calculix-ccx)")
    work = pathlib.Path(args.work)
    work.mkdir(exist_ok=True)
    subprocess.run([sys.executable, str(HERE / "parts.py"), "beam", str(work / "beam.obj")], check=True)
    command = [args.meshprep, "pipeline", str(work / "beam.obj"), "-o", str(work / "mesh"), "--format", "inp",
               "--config", str(HERE / "cantilever.json"), "--quiet"]
    if args.order == 2:
        command += ["--order", "2"]
    for size in args.size:
        command += ["--size", size]
    subprocess.run(command, check=True)
    shutil.copy(work / "mesh" / "tets.inp", work / "tets.inp")
    shutil.copy(HERE / "cantilever.inp", work / "cantilever.inp")
    ccx = subprocess.run(["ccx", "-i", "cantilever"], cwd=work, capture_output=True, text=True)
    if ccx.returncode != 0 or "*ERROR" in ccx.stdout:
        sys.exit(f"ccx failed (exit {ccx.returncode}):\n{ccx.stdout[-2000:]}")
    rows = printed_displacements(work / "cantilever.dat")
    if not rows:
        sys.exit(f"{work / 'cantilever.dat'}: no displacements of the free end")
    tip = -sum(row[1] for row in rows) / len(rows)
    theory = euler_bernoulli_tip_deflection()
    element = "C3D10" if args.order == 2 else "C3D4"
    print(f"{element}: tip deflection {tip:.6g} mm, Euler-Bernoulli {theory:.6g} mm, ratio {tip / theory:.4f}")


if __name__ == "__main__":
    main()
