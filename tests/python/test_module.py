"""The Python module (issue 46): arrays in and out, the same figures as the command line, errors as
exceptions, calls that release the GIL and stop on Ctrl-C or a CancelToken.

Run by ctest (python_module) with PYTHONPATH=build/python and MESHPREP_BIN=build/bin/meshprep."""

import json
import os
import signal
import subprocess
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import meshprep

HERE = Path(__file__).resolve().parent
DATA = HERE.parent / "data"
EXAMPLES = HERE.parent.parent / "examples" / "data"
BIN = os.environ.get("MESHPREP_BIN", str(HERE.parent.parent / "build" / "bin" / "meshprep"))


def cube_surface(scale=1.0):
    points = scale * np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                               [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], dtype=np.float64)
    faces = np.array([[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
                      [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]], dtype=np.int64)
    return points, faces


def run_cli(*args):
    return subprocess.run([BIN, *map(str, args)], capture_output=True, text=True)


# Keys whose values are not figures of the mesh: times, paths, machine facts.
NOT_FIGURES = {"time_seconds", "seconds", "tetgen_seconds", "path", "file", "input", "output", "reference"}


def assert_same_figures(a, b, where="report"):
    """Every figure of `a` equals `b`'s to 1e-12 relative (times and names aside)."""
    if isinstance(a, dict):
        assert isinstance(b, dict), where
        for key in a.keys() & b.keys():
            if key not in NOT_FIGURES and not key.endswith("_seconds"):
                assert_same_figures(a[key], b[key], f"{where}.{key}")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b)):
            assert_same_figures(x, y, f"{where}[{i}]")
    elif isinstance(a, float) or isinstance(b, float):
        assert a == pytest.approx(b, rel=1e-12, abs=0), where
    else:
        assert a == b, where


def test_surface_arrays_are_views_of_one_copy():
    points, faces = cube_surface()
    surface = meshprep.Surface(points, faces)
    assert surface.points.dtype == np.float64 and surface.points.shape == (8, 3)
    assert surface.faces.dtype == np.uint32 and surface.faces.shape == (12, 3)
    np.testing.assert_array_equal(surface.points, points)
    np.testing.assert_array_equal(surface.faces, faces)
    assert not np.shares_memory(surface.points, points)  # the one copy in
    assert np.shares_memory(surface.points, surface.points)  # no copy out: the same storage each time
    assert surface.points.__array_interface__["data"][0] == surface.points.__array_interface__["data"][0]
    with pytest.raises(ValueError):
        surface.points[0, 0] = 5  # read-only: the mesh is only changed by meshprep's calls
    view = surface.points
    del surface
    assert view[1, 0] == 1.0  # the view keeps the mesh alive


BAD_SURFACES = [
    ("float32 points", lambda p, f: (p.astype(np.float32), f), "float64"),
    ("(n, 2) points", lambda p, f: (np.ascontiguousarray(p[:, :2]), f), "shape"),
    ("negative index", lambda p, f: (p, np.where(f == 3, -1, f)), "outside"),
    ("index past the end", lambda p, f: (p, np.where(f == 7, 8, f)), "outside"),
    ("NaN point", lambda p, f: (np.where(p == 1, np.nan, p), f), "not finite"),
    ("infinite point", lambda p, f: (np.where(p == 1, np.inf, p), f), "not finite"),
    ("non-contiguous points", lambda p, f: (np.asfortranarray(p), f), "contiguous"),
    ("non-contiguous faces", lambda p, f: (p, np.asfortranarray(f)), "contiguous"),
    ("float faces", lambda p, f: (p, f.astype(np.float64)), "integer"),
    ("no points", lambda p, f: (np.zeros((0, 3)), f), "empty"),
    ("no faces", lambda p, f: (p, np.zeros((0, 3), dtype=np.int64)), "empty"),
]


@pytest.mark.parametrize("name,make,message", BAD_SURFACES, ids=[b[0] for b in BAD_SURFACES])
def test_bad_arrays_raise_input_error(name, make, message):
    points, faces = make(*cube_surface())
    with pytest.raises(meshprep.InputError, match=message):
        meshprep.Surface(points, faces)


def test_random_arrays_never_crash():
    rng = np.random.default_rng(46)
    dtypes = [np.float64, np.float32, np.int64, np.int32, np.uint8, np.bool_]
    for _ in range(1000):
        shape_p = tuple(int(s) for s in rng.integers(0, 5, size=rng.integers(1, 4)))
        shape_f = tuple(int(s) for s in rng.integers(0, 5, size=rng.integers(1, 4)))
        with np.errstate(all="ignore"):  # float64 -> float32 overflows to inf: part of the test
            points = (rng.normal(size=shape_p) * 10.0 ** float(rng.integers(-3, 300))).astype(rng.choice(dtypes))
        faces = rng.integers(-2, 6, size=shape_f).astype(rng.choice(dtypes))
        try:
            surface = meshprep.Surface(points, faces)
        except meshprep.InputError:
            continue
        meshprep.quality(surface, distance_samples=1000)  # what is accepted can be measured


def test_unknown_and_out_of_range_keywords_raise_before_work():
    surface = meshprep.Surface(*cube_surface())
    with pytest.raises(meshprep.InputError, match="unknown keyword 'min_angle'.*min_angle_deg"):
        meshprep.simplify(surface, ratio=0.5, min_angle=10)
    with pytest.raises(meshprep.InputError, match=r"simplify.min_angle_deg.*\[0, 60\)"):
        meshprep.simplify(surface, ratio=0.5, min_angle_deg=70)
    with pytest.raises(meshprep.InputError, match="exactly one of ratio and target_faces"):
        meshprep.simplify(surface)
    with pytest.raises(meshprep.InputError, match="verdict.max_dihedral_deg"):
        meshprep.tetrahedralize(surface, verdict={"max_dihedral_deg": 400})
    with pytest.raises(meshprep.InputError, match="threads: expected an integer >= 0"):
        meshprep.quality(surface, threads=-1)
    assert "min_angle_deg (number in [0, 60), default 20.0)" in meshprep.simplify.__doc__


def test_exit_codes_are_the_command_lines():
    assert meshprep.InputError.exit_code == 2
    assert meshprep.NotReadyError.exit_code == 1
    assert meshprep.WorkError.exit_code == 3
    assert meshprep.TimeoutError.exit_code == 124
    assert meshprep.Cancelled.exit_code == 130
    assert issubclass(meshprep.InputError, meshprep.Error) and issubclass(meshprep.InputError, ValueError)


def test_read_errors_name_the_file(tmp_path):
    missing = tmp_path / "missing.off"
    with pytest.raises(meshprep.InputError, match="missing.off"):
        meshprep.read(missing)
    broken = tmp_path / "broken.off"
    broken.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n")
    with pytest.raises(meshprep.InputError, match="broken.off"):
        meshprep.read(broken)


@pytest.mark.parametrize("scale", [1.0, 1000.0])
def test_cube_to_tets_is_fem_ready(scale, tmp_path):
    result = meshprep.tetrahedralize(meshprep.Surface(*cube_surface(scale)))
    assert result.fem_ready
    tets = result.tets
    assert tets.tets.shape[1] == 4 and tets.tets.shape[0] >= 5
    volume = result.report["tet_quality"]["volume"]
    assert volume == pytest.approx(scale ** 3, rel=1e-12)
    out = tmp_path / "cube.msh"
    tets.write(out)
    back = meshprep.read(out)
    np.testing.assert_array_equal(back.tets, tets.tets)


def test_not_ready_error_carries_the_result():
    with pytest.raises(meshprep.NotReadyError) as caught:
        meshprep.tetrahedralize(meshprep.Surface(*cube_surface()), verdict={"min_dihedral_deg": 80})
    assert caught.value.result.tets is not None
    assert caught.value.report["fem_ready"] is False


def test_open_surface_is_refused_as_bad_input():
    points, faces = cube_surface()
    with pytest.raises(meshprep.InputError, match="not FEM-ready"):
        meshprep.tetrahedralize(meshprep.Surface(points, faces[:-1]))


def test_time_limit_ends_the_improvement_with_its_best_tets():
    # A limit that has passed before the improvement starts: TetGen's tets as they are, and the
    # report says why; the tets are usable (not a TimeoutError).
    tets = slow_tets()
    result = meshprep.improve(tets, time_limit=1e-9, verdict={"min_dihedral_deg": 0, "max_dihedral_deg": 180})
    assert result.report["stopped"] == "time limit"
    assert result.report["improvement"]["stopped_by"] == "time limit"
    assert result.tets.tets.shape == tets.tets.shape


def test_time_limit_ends_the_enhancement_with_its_best_rounds():
    # Anytime too: at the deadline no round starts; the surface so far (here the input's faces) is
    # the result, marked, not a TimeoutError. Without a limit the rounds run.
    surface = meshprep.read(DATA / "handle.off")
    result = meshprep.enhance(surface, time_limit=1e-9)
    assert result.report["stopped"] == "time limit" and result.report["rounds"] == 0
    assert result.surface.faces.shape == surface.faces.shape
    free = meshprep.enhance(surface, time_limit_seconds=0)
    assert free.report["stopped"] is None and free.report["rounds"] > 0


def test_time_limit_before_anything_usable_raises_timeout_error():
    surface = meshprep.read(DATA / "handle.off")
    with pytest.raises(meshprep.TimeoutError, match="time_limit") as caught:
        meshprep.simplify(surface, ratio=0.5, time_limit=1e-9)
    assert caught.value.exit_code == 124
    with pytest.raises(meshprep.InputError, match="time_limit"):
        meshprep.simplify(surface, ratio=0.5, time_limit=-1)


def test_simplify_gives_the_command_lines_figures_and_file(tmp_path):
    source = DATA / "handle.off"
    cli_out, cli_json = tmp_path / "cli.off", tmp_path / "cli.json"
    run = run_cli("simplify", source, "-o", cli_out, "--ratio", "0.3", "--samples", "20000", "--json", cli_json)
    assert run.returncode == 0, run.stderr
    result = meshprep.simplify(meshprep.read(source), ratio=0.3, quality={"distance_samples": 20000})
    assert_same_figures(result.report, json.loads(cli_json.read_text()))
    py_out = tmp_path / "py.off"
    result.surface.write(py_out)
    assert py_out.read_bytes() == cli_out.read_bytes()


@pytest.mark.parametrize("cli_args, keywords, reason", [
    (["--route", "envelope"], {"route": "envelope"}, "asked (route envelope)"),
    (["--repair-time-limit", "1e-9"], {"time_limit_seconds": 1e-9}, "the exact cut was not done"),
])
def test_repair_takes_the_envelope_route_as_the_command_line_does(tmp_path, cli_args, keywords, reason):
    # Two unit cubes overlapping by half, on a 32-cell grid: the route asked for by the command
    # line's names, and the automatic route past a time limit that passed before the exact cut's
    # first look at the clock.
    points, faces = cube_surface()
    shifted = points + np.array([0.5, 0.25, 0.25])
    source = tmp_path / "two_cubes.off"
    meshprep.Surface(np.vstack([points, shifted]), np.vstack([faces, faces + 8])).write(source)
    cli_out, cli_json = tmp_path / "cli.off", tmp_path / "cli.json"
    run = run_cli("repair", source, "-o", cli_out, *cli_args, "--envelope-cells", "32", "--json", cli_json)
    assert run.returncode == 0, run.stderr
    result = meshprep.repair(meshprep.read(source), envelope_cells=32, **keywords)
    assert result.report["route"] == "envelope"
    assert result.report["envelope"]["cells"] == 32
    assert result.report["envelope"]["reason"].startswith(reason)
    assert_same_figures(result.report, json.loads(cli_json.read_text()))
    py_out = tmp_path / "py.off"
    result.surface.write(py_out)
    assert py_out.read_bytes() == cli_out.read_bytes()


def test_tetrahedralize_gives_the_command_lines_figures_and_file(tmp_path):
    source = DATA / "example004.stl"
    cli_out, cli_json = tmp_path / "cli.msh", tmp_path / "cli.json"
    run = run_cli("tetrahedralize", source, "-o", cli_out, "--json", cli_json)
    assert run.returncode in (0, 1), run.stderr
    try:
        result = meshprep.tetrahedralize(meshprep.read(source))
    except meshprep.NotReadyError as e:
        result = e.result
    assert_same_figures(result.report, json.loads(cli_json.read_text()))
    py_out = tmp_path / "py.msh"
    result.tets.write(py_out)
    assert py_out.read_bytes() == cli_out.read_bytes()


@pytest.mark.parametrize("keywords", [{"size": "10%"}, {"size": {"size": "10%", "grading": 1.3}}])
def test_size_keyword_is_the_command_lines_size(tmp_path, keywords):
    """size="10%" is size={"size": "10%"} and --size 10%: the same tets, their edges on the size."""
    points, faces = cube_surface()
    source = tmp_path / "cube.off"
    meshprep.Surface(points, faces).write(source)
    cli_json = tmp_path / "cli.json"
    run = run_cli("tetrahedralize", source, "-o", tmp_path / "cli.msh", "--size", "10%", "--json", cli_json)
    assert run.returncode == 0, run.stderr
    result = meshprep.tetrahedralize(meshprep.Surface(points, faces), **keywords)
    report = json.loads(cli_json.read_text())
    assert_same_figures(result.report, report)
    assert "m" in report["switches"]
    # 10 % of the diagonal (0.173): TetGen's sizes stop the edges under 1.5 h, most in [0.7, 1.4] h.
    assert report["size_conformity"]["within_band"]["share"] >= 0.9
    assert report["size_conformity"]["ratio"]["p99"] <= 1.5


def test_patch_sizes_are_the_command_lines(tmp_path):
    """size={"patches": {...}} is --size NAME=LENGTH: the same tets, finer on that patch; an unknown
    name is bad input, named with the surface's patches."""
    points, faces = cube_surface()
    source = tmp_path / "cube.off"
    meshprep.Surface(points, faces).write(source)
    cli_json = tmp_path / "cli.json"
    run = run_cli("tetrahedralize", source, "-o", tmp_path / "cli.msh", "--size", "20%", "--size", "patch_1=5%",
                  "--json", cli_json)
    assert run.returncode == 0, run.stderr
    result = meshprep.tetrahedralize(meshprep.Surface(points, faces), size={"size": "20%", "patches": {"patch_1": "5%"}})
    assert_same_figures(result.report, json.loads(cli_json.read_text()))
    tets = result.tets
    tag = {name: tag for tag, name in tets.patch_names.items()}
    faces_on = {name: int((tets.patches == tag[name]).sum()) for name in ("patch_1", "patch_2")}
    # Sizes 4x finer: about 16x the faces on an equal face of the cube.
    assert faces_on["patch_1"] >= 8 * faces_on["patch_2"], faces_on
    with pytest.raises(meshprep.InputError, match="no patch named 'patch_9'"):
        meshprep.tetrahedralize(meshprep.Surface(points, faces), size={"patches": {"patch_9": "5%"}})


def test_pipeline_gives_the_command_lines_summary(tmp_path):
    source = DATA / "example004.stl"
    run = run_cli("pipeline", source, "-o", tmp_path / "cli", "--quiet")
    assert run.returncode in (0, 1), run.stderr
    try:
        result = meshprep.pipeline(source, tmp_path / "py")
    except meshprep.NotReadyError as e:
        result = e.result
    cli_report = json.loads((tmp_path / "cli" / "report.json").read_text())
    assert_same_figures(result.report, cli_report)
    assert (tmp_path / "py" / "tets.msh").read_bytes() == (tmp_path / "cli" / "tets.msh").read_bytes()


def test_pipeline_on_a_surface_in_memory_gives_the_files_figures():
    source = DATA / "example004.stl"
    outcomes = []
    for given in (source, meshprep.read(source)):
        try:
            outcomes.append(meshprep.pipeline(given, improve=False))
        except meshprep.NotReadyError as e:
            outcomes.append(e.result)
    assert outcomes[1].report["input"] == "<surface>"
    assert_same_figures(outcomes[1].report, outcomes[0].report)
    np.testing.assert_array_equal(outcomes[1].tets.tets, outcomes[0].tets.tets)


def test_pipeline_takes_the_knife_edges_section_as_the_config_file_does():
    source = DATA / "example004.stl"
    for given, ran in ((False, False), ({"enabled": True}, True)):
        try:
            result = meshprep.pipeline(source, knife_edges=given, improve=False)
        except meshprep.NotReadyError as e:
            result = e.result
        stage = next(s for s in result.report["stages"] if s["name"] == "knife_edges")
        assert stage["ran"] == ran
        if ran:
            details = stage["details"]
            assert details["knife_edges_after"] <= details["knife_edges_before"]
            assert len(details["left"]) == details["knife_edges_after"]


def test_progress_reaches_the_callback_and_can_stop_the_work():
    surface = meshprep.read(DATA / "handle.off")
    seen = []
    few = {"distance_samples": 1000}  # the report's figures are not the point here
    meshprep.simplify(surface, ratio=0.9, quality=few, progress=lambda stage, f: seen.append((stage, f)))
    assert seen and all(stage == "simplify" and 0 <= f <= 1 for stage, f in seen)

    class Stop(Exception):
        pass

    def stop(stage, fraction):
        raise Stop()

    with pytest.raises(Stop):
        meshprep.simplify(surface, ratio=0.9, quality=few, progress=stop)


def slow_tets():
    """A cube filled with many small tets: improving them takes seconds."""
    return meshprep.tetrahedralize(meshprep.Surface(*cube_surface()), max_volume_relative=1e-5, improve=False,
                                   verdict={"min_dihedral_deg": 0, "max_dihedral_deg": 180}).tets


def test_cancel_token_stops_improve_and_nothing_is_written(tmp_path):
    tets = slow_tets()
    token = meshprep.CancelToken()
    threading.Timer(0.2, token.cancel).start()
    with pytest.raises(meshprep.Cancelled):
        meshprep.improve(tets, cancel=token, goal_min_dihedral_deg=59, max_passes=1000)
    assert list(tmp_path.iterdir()) == []


def test_ctrl_c_stops_improve_with_keyboard_interrupt():
    tets = slow_tets()
    threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
    with pytest.raises(KeyboardInterrupt):
        meshprep.improve(tets, goal_min_dihedral_deg=59, max_passes=1000)


def test_two_threads_simplify_at_once_and_get_the_serial_results():
    surface = meshprep.read(DATA / "handle.off")
    few = {"distance_samples": 1000}  # the report's figures are not the point here
    serial = [meshprep.simplify(surface, ratio=r, quality=few).surface for r in (0.85, 0.9)]
    results = [None, None]

    def work(i, ratio):  # each on one thread of its own (threads=1): the same surface as on all cores
        results[i] = meshprep.simplify(surface, ratio=ratio, quality=few, threads=1).surface

    threads = [threading.Thread(target=work, args=(i, r)) for i, r in enumerate((0.85, 0.9))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, b in zip(serial, results):
        np.testing.assert_array_equal(a.points, b.points)
        np.testing.assert_array_equal(a.faces, b.faces)


def test_meshio_round_trip():
    meshio = pytest.importorskip("meshio")
    surface = meshprep.Surface(*cube_surface())
    back = meshprep.Surface.from_meshio(surface.to_meshio())
    np.testing.assert_array_equal(back.points, surface.points)
    tets = meshprep.tetrahedralize(surface).tets
    mesh = tets.to_meshio()
    assert isinstance(mesh, meshio.Mesh)
    again = meshprep.TetMesh.from_meshio(mesh)
    np.testing.assert_array_equal(again.tets, tets.tets)


def test_dolfinx_reads_what_a_tet_mesh_writes(tmp_path):
    pytest.importorskip("dolfinx", reason="dolfinx is not importable (apt-get install python3-dolfinx)")
    from dolfinx import fem, io
    from mpi4py import MPI
    import ufl
    tets = meshprep.tetrahedralize(meshprep.Surface(*cube_surface(2.0))).tets
    tets.write(tmp_path / "cube.xdmf")
    with io.XDMFFile(MPI.COMM_WORLD, str(tmp_path / "cube.xdmf"), "r") as xdmf:
        mesh = xdmf.read_mesh(name="mesh")
    assert mesh.topology.index_map(3).size_global == len(tets.tets)
    volume = fem.assemble_scalar(fem.form(1.0 * ufl.dx(domain=mesh)))
    assert volume == pytest.approx(8.0, rel=1e-12)
