"""The Python module gives the command line's figures and files (issue 46, acceptance 2).

On the three bundled examples and five files of ../shared/data (two CAD parts, two scans, a point
set): `meshprep.pipeline()` against `meshprep pipeline` (report.json's figures to 1e-12 relative,
the same surface.ply and tets.msh, byte for byte), and the stage-by-stage chain
simplify -> enhance -> tetrahedralize in memory against the same commands through files (OFF and
.msh: their numbers are written as the shortest text that reads back to the same double, so the
files do not change the figures). Shared files are skipped when ../shared/data is missing.

Run by ctest (python_equivalence) with PYTHONPATH=build/python, MESHPREP_BIN and MESHPREP_SHARED_DATA."""

import json
import os
import subprocess
from pathlib import Path

import pytest

import meshprep
from test_module import assert_same_figures

HERE = Path(__file__).resolve().parent
EXAMPLES = HERE.parent.parent / "examples" / "data"
SHARED = Path(os.environ.get("MESHPREP_SHARED_DATA") or HERE.parents[2] / "shared" / "data")
BIN = os.environ.get("MESHPREP_BIN", str(HERE.parent.parent / "build" / "bin" / "meshprep"))

# (name, file, the pipeline's flags and the same as Python keywords), as examples/pipeline_examples.txt runs them.
PIPELINES = [
    ("terrain", EXAMPLES / "jacksboro_10k.xyz", [], {}),
    ("fandisk", EXAMPLES / "fandisk.off", ["--ratio", "0.3"], {"simplify": {"ratio": 0.3}}),
    ("femur", EXAMPLES / "femur.off", [], {}),
    ("cad example002", SHARED / "cad" / "example002.stl", [], {}),
    ("cad LetterBlock", SHARED / "cad" / "LetterBlock.stl", [], {}),
    ("scan bull", SHARED / "corpus" / "bull.off", ["--ratio", "0.5"], {"simplify": {"ratio": 0.5}}),
    ("scan elk", SHARED / "corpus" / "elk.off", ["--ratio", "0.5"], {"simplify": {"ratio": 0.5}}),
    ("points jacksboro_grid", SHARED / "points" / "jacksboro_grid.xyz", [], {}),
]


def need(path):
    if not path.exists():
        pytest.skip(f"{path} not found (../shared/data lives beside the clone in CI)")


def cli(*args, ok=(0,)):
    run = subprocess.run([BIN, *map(str, args)], capture_output=True, text=True)
    assert run.returncode in ok, run.stderr
    return run


def judged(call):
    try:
        return call()
    except meshprep.NotReadyError as e:
        return e.result


@pytest.mark.parametrize("name,source,flags,sections", PIPELINES, ids=[p[0] for p in PIPELINES])
def test_pipeline_matches_the_command_line(name, source, flags, sections, tmp_path):
    need(source)
    cli("pipeline", source, "-o", tmp_path / "cli", "--quiet", *flags, ok=(0, 1))
    result = judged(lambda: meshprep.pipeline(str(source), tmp_path / "py", **sections))
    assert_same_figures(result.report, json.loads((tmp_path / "cli" / "report.json").read_text()))
    for output in ("surface.ply", "tets.msh", "report.vtu"):
        assert (tmp_path / "py" / output).read_bytes() == (tmp_path / "cli" / output).read_bytes(), output


CHAINS = [p for p in PIPELINES if p[1].suffix != ".xyz"][:5]


@pytest.mark.parametrize("name,source,flags,sections", CHAINS, ids=[p[0] for p in CHAINS])
def test_stage_by_stage_chain_matches_the_commands(name, source, flags, sections, tmp_path):
    need(source)
    samples = {"distance_samples": 20000}
    cli("simplify", source, "-o", tmp_path / "s.off", "--ratio", "0.5", "--samples", "20000", "--json", tmp_path / "s.json")
    cli("enhance", tmp_path / "s.off", "-o", tmp_path / "e.off", "--samples", "20000", "--json", tmp_path / "e.json")
    cli("tetrahedralize", tmp_path / "e.off", "-o", tmp_path / "t.msh", "--json", tmp_path / "t.json", ok=(0, 1))

    simplified = meshprep.simplify(meshprep.read(source), ratio=0.5, quality=samples)
    enhanced = meshprep.enhance(simplified.surface, quality=samples)
    tets = judged(lambda: meshprep.tetrahedralize(enhanced.surface))
    for result, record in ((simplified, "s.json"), (enhanced, "e.json"), (tets, "t.json")):
        assert_same_figures(result.report, json.loads((tmp_path / record).read_text()), record)
    enhanced.surface.write(tmp_path / "py_e.off")
    tets.tets.write(tmp_path / "py_t.msh")
    assert (tmp_path / "py_e.off").read_bytes() == (tmp_path / "e.off").read_bytes()
    assert (tmp_path / "py_t.msh").read_bytes() == (tmp_path / "t.msh").read_bytes()
