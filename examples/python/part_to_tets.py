"""A part to FEM-ready tets from Python, stage by stage, with the figures of each step.

Usage (from the repository root, after the README's build):
    PYTHONPATH=build/python /usr/bin/python3 examples/python/part_to_tets.py examples/data/fandisk.off fandisk.inp
"""

import sys

import meshprep


def main(source, target):
    part = meshprep.read(source)
    print(part)
    enhanced = meshprep.enhance(part, progress=lambda stage, f: print(f"\r{stage} {100 * f:3.0f} %", end=""))
    before, after = enhanced.report["tail_before"], enhanced.report["tail_after"]
    print(f"\nenhance: smallest angle {before['min_angle_deg']:.1f} -> {after['min_angle_deg']:.1f} deg")
    try:
        result = meshprep.tetrahedralize(enhanced.surface, verdict={"min_dihedral_deg": 10})
    except meshprep.NotReadyError as e:  # the tets are made, but fail a threshold
        print("not FEM-ready:", e)
        result = e.result
    quality = result.report["tet_quality"]
    print(f"{quality['tetrahedra']} tets, smallest dihedral {quality['min_dihedral_deg']['min']:.1f} deg")
    result.tets.write(target)
    print("wrote", target)
    return 0 if result.fem_ready else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:3]))
