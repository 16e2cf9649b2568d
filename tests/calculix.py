#!/usr/bin/env python3
"""Runs CalculiX (ccx) on a tetrahedral mesh that meshprep wrote as an Abaqus deck (.inp).

Usage: calculix.py MESH.inp [--fix NSET] [--pressure SURFACE] [--print-elset ELSET] [--keep DIR]

Builds a static job around the mesh (static_deck): the mesh *INCLUDEd as it is; one linear elastic
material with a density, given to every region's element set (*SOLID SECTION); NSET fixed
(*BOUNDARY, all three displacements; default the first *NSET); gravity on every region (*DLOAD
GRAV) and a pressure on SURFACE (*DSLOAD; default the first *SURFACE); displacements and stresses
into the .frd, the total reaction of NSET and the stresses of ELSET (default the first *ELSET, a
patch's tets) into the .dat. Runs `ccx -i job` in a scratch folder (DIR with --keep) and checks:
exit code 0 and no *ERROR or *WARNING in what ccx prints; a displacement block in the .frd with one
finite row per node, not all zero (gravity moves the nodes NSET leaves free); in the .dat the total
force of NSET (three finite numbers) and one stress row per element of ELSET.

Prints one line; exits 0 when everything holds, 1 with the reason when something does not, 77
when ccx is not on PATH (a test skips), 2 on bad usage. Standard library only.

The pieces (read_deck, static_deck, run_ccx, read_frd_block, read_dat_blocks) are for further
solver tests to reuse, e.g. a cantilever whose end patches are named.
"""
import argparse
import math
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

# Steel in N, mm, tonne, s: what the figures mean matters less than that they are plausible.
YOUNG_MODULUS = 210000.0
POISSON_RATIO = 0.3
DENSITY = 7.85e-9
GRAVITY = 9810.0
PRESSURE = 1.0
CCX_TIMEOUT_SECONDS = 600


class Failure(Exception):
    pass


def keyword_parameters(line):
    """'*NSET, NSET=top' -> ('*NSET', {'NSET': 'top'}); keys upper-case, values as written."""
    fields = [field.strip() for field in line.split(",")]
    parameters = {}
    for field in fields[1:]:
        key, _, value = field.partition("=")
        parameters[key.strip().upper()] = value.strip()
    return fields[0].upper(), parameters


class Deck:
    """What a mesh deck defines: the node count, region element sets, node sets, element sets
    and surfaces (each name with its ids or element-face lines), in file order."""

    def __init__(self):
        self.nodes = 0
        self.regions = {}   # ELSET of an *ELEMENT block -> element ids
        self.nsets = {}     # -> node ids
        self.elsets = {}    # *ELSET blocks -> element ids
        self.surfaces = {}  # -> [(element id, face label)]


def read_deck(path):
    deck = Deck()
    target = None  # (kind, name) the data lines belong to
    with open(path, encoding="ascii") as lines:
        for number, line in enumerate(lines, 1):
            line = line.strip()
            if not line or line.startswith("**"):
                continue
            if line.startswith("*"):
                keyword, parameters = keyword_parameters(line)
                target = None
                if keyword == "*NODE":
                    target = ("node", None)
                elif keyword == "*ELEMENT":
                    name = parameters.get("ELSET", "")
                    deck.regions.setdefault(name, [])
                    target = ("region", name)
                elif keyword == "*NSET":
                    target = ("nset", parameters["NSET"])
                    deck.nsets.setdefault(target[1], [])
                elif keyword == "*ELSET":
                    target = ("elset", parameters["ELSET"])
                    deck.elsets.setdefault(target[1], [])
                elif keyword == "*SURFACE":
                    target = ("surface", parameters["NAME"])
                    deck.surfaces.setdefault(target[1], [])
                continue
            if target is None:
                continue
            fields = [field.strip() for field in line.split(",") if field.strip()]
            kind, name = target
            try:
                if kind == "node":
                    deck.nodes += 1
                elif kind == "region":
                    deck.regions[name].append(int(fields[0]))
                elif kind == "nset":
                    deck.nsets[name].extend(int(field) for field in fields)
                elif kind == "elset":
                    deck.elsets[name].extend(int(field) for field in fields)
                else:
                    deck.surfaces[name].append((int(fields[0]), fields[1]))
            except (ValueError, IndexError) as error:
                raise Failure(f"{path}:{number}: cannot read '{line}': {error}") from error
    return deck


def static_deck(mesh_file, deck, fix_nset, pressure_surface, print_elset):
    """The text of a static job on the mesh (see the module's description)."""
    job = [f"*INCLUDE, INPUT={mesh_file}",
           "*MATERIAL, NAME=MESHPREP_STEEL", "*ELASTIC", f"{YOUNG_MODULUS}, {POISSON_RATIO}",
           "*DENSITY", f"{DENSITY}"]
    job += [f"*SOLID SECTION, ELSET={region}, MATERIAL=MESHPREP_STEEL" for region in deck.regions]
    job += ["*BOUNDARY", f"{fix_nset}, 1, 3", "*STEP", "*STATIC", "*DLOAD"]
    job += [f"{region}, GRAV, {GRAVITY}, 0., 0., -1." for region in deck.regions]
    job += ["*DSLOAD", f"{pressure_surface}, P, {PRESSURE}",
            "*NODE FILE", "U", "*EL FILE", "S",
            f"*NODE PRINT, NSET={fix_nset}, TOTALS=ONLY", "RF",
            f"*EL PRINT, ELSET={print_elset}", "S",
            "*END STEP"]
    return "\n".join(job) + "\n"


def run_ccx(directory, job="job"):
    """Runs `ccx -i JOB` in DIRECTORY; returns what it printed. Raises Failure on a non-zero exit
    code or an *ERROR or *WARNING line."""
    try:
        run = subprocess.run(["ccx", "-i", job], cwd=directory, capture_output=True, text=True,
                             timeout=CCX_TIMEOUT_SECONDS)
    except (OSError, subprocess.TimeoutExpired) as error:
        raise Failure(f"cannot run ccx -i {job}: {error}") from error
    output = run.stdout + run.stderr
    problems = [line.strip() for line in output.splitlines() if re.match(r"\s*\*(ERROR|WARNING)", line)]
    if run.returncode != 0 or problems:
        lines = output.splitlines()
        first = next((i for i, line in enumerate(lines) if re.match(r"\s*\*(ERROR|WARNING)", line)), len(lines) - 3)
        context = " | ".join(line.strip() for line in lines[max(first, 0):first + 3] if line.strip())
        raise Failure(f"ccx -i {job} exit code {run.returncode}: {context}")
    return output


def read_frd_block(path, name):
    """The first result block NAME (e.g. DISP, STRESS) of a .frd file: {node: [values]}. Data lines
    are ' -1', the node in 10 columns, then values in 12 columns each (they may touch)."""
    values, inside = {}, False
    with open(path, encoding="ascii", errors="replace") as lines:
        for line in lines:
            if not inside:
                inside = line.startswith(" -4") and line[3:].split()[0] == name
                continue
            if line.startswith(" -3"):
                return values
            if line.startswith(" -1"):
                body = line.rstrip("\n")
                values[int(body[3:13])] = [float(body[k:k + 12]) for k in range(13, len(body), 12)]
    if not inside:
        raise Failure(f"{path}: no {name} block")
    raise Failure(f"{path}: the {name} block does not end")


def read_dat_blocks(path):
    """The blocks of a .dat file: {title: [rows of numbers]}, the title being the header line up
    to ' and time' ('total force (fx,fy,fz) for set FIXED', 'stresses (elem, ...) for set S')."""
    blocks, title = {}, None
    with open(path, encoding="ascii", errors="replace") as lines:
        for line in lines:
            text = line.strip()
            if not text:
                continue
            if " for set " in text:
                title = text.split(" and time")[0]
                blocks[title] = []
            elif title is not None:
                blocks[title].append([float(field) for field in text.split()])
    return blocks


def check_results(directory, deck, fix_nset, print_elset, job="job"):
    displacements = read_frd_block(directory / f"{job}.frd", "DISP")
    if len(displacements) != deck.nodes:
        raise Failure(f"the .frd has {len(displacements)} displacement rows for {deck.nodes} nodes")
    largest = 0.0
    for node, values in displacements.items():
        if len(values) != 3 or not all(math.isfinite(v) for v in values):
            raise Failure(f"node {node}: displacement {values}")
        largest = max(largest, max(abs(v) for v in values))
    if largest == 0.0:
        raise Failure("every displacement is 0: the loads reached no free node")
    blocks = read_dat_blocks(directory / f"{job}.dat")
    total = blocks.get(f"total force (fx,fy,fz) for set {fix_nset.upper()}")
    if not total or len(total[0]) != 3 or not all(math.isfinite(v) for v in total[0]):
        raise Failure(f"no total force of {fix_nset} in the .dat (blocks: {sorted(blocks)})")
    stresses = next((rows for title, rows in blocks.items()
                     if title.startswith("stresses") and title.endswith(f"set {print_elset.upper()}")), None)
    expected = len(deck.elsets.get(print_elset, deck.regions.get(print_elset, [])))
    if stresses is None or len(stresses) != expected:
        found = "none" if stresses is None else len(stresses)
        raise Failure(f"the .dat has {found} stress rows for the {expected} elements of {print_elset}")
    return (f"{deck.nodes} nodes, largest displacement {largest:.3g}, reaction of {fix_nset} "
            f"{total[0][2]:.4g} (z), {len(stresses)} stress rows for {print_elset}")


def first(names, what, path):
    if not names:
        raise Failure(f"{path}: no {what}")
    return next(iter(names))


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mesh")
    parser.add_argument("--fix")
    parser.add_argument("--pressure")
    parser.add_argument("--print-elset")
    parser.add_argument("--keep", help="run in this folder (kept) instead of a scratch one")
    args = parser.parse_args(argv[1:])
    if shutil.which("ccx") is None:
        print("SKIP: ccx is not on PATH (apt-get install calculix-ccx)")
        return 77
    mesh = pathlib.Path(args.mesh)
    try:
        deck = read_deck(mesh)
        fix = args.fix or first(deck.nsets, "*NSET", mesh)
        surface = args.pressure or first(deck.surfaces, "*SURFACE", mesh)
        elset = args.print_elset or first(deck.elsets, "*ELSET", mesh)
        with tempfile.TemporaryDirectory(prefix="meshprep-ccx-") as scratch:
            directory = pathlib.Path(args.keep or scratch)
            directory.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(mesh, directory / "mesh.inp")
            (directory / "job.inp").write_text(static_deck("mesh.inp", deck, fix, surface, elset), encoding="ascii")
            run_ccx(directory)
            summary = check_results(directory, deck, fix, elset)
    except (Failure, OSError) as failure:
        print(f"FAIL {mesh}: {failure}")
        return 1
    print(f"ok   {mesh}: ccx exit 0: {summary}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
