"""meshprep from Python: meshes as numpy arrays, one function per command of the `meshprep` tool.

    import meshprep
    part = meshprep.read("part.stl")
    result = meshprep.tetrahedralize(meshprep.repair(part).surface)
    result.tets.write("part.inp")

Keywords are the configuration file's keys (docs/pipeline.md), with the command line's defaults;
docs/python.md has the data model, the errors and examples. Every call releases the GIL, stops on
Ctrl-C (KeyboardInterrupt) or a CancelToken, and reports progress to progress(stage, fraction).
"""

import json as _json

from ._meshprep import (  # noqa: F401  (the public names)
    CancelToken,
    Cancelled,
    Error,
    InputError,
    NotReadyError,
    Surface,
    TetMesh,
    TimeoutError,
    WorkError,
    read,
)
from . import _meshprep

__all__ = [
    "CancelToken", "Cancelled", "Error", "InputError", "NotReadyError", "Result", "Surface", "TetMesh",
    "TimeoutError", "WorkError", "check", "enhance", "improve", "pipeline", "quality", "read", "reconstruct",
    "repair", "simplify", "smooth", "tetrahedralize",
]


class Result:
    """What a call made and measured.

    surface / tets: the mesh made (None when the call makes none); report: the figures the command
    line's --json writes for the same work (a dict); fem_ready: the verdict where the call gives
    one (else None); messages: the notes and warnings the command line prints.
    """

    def __init__(self, raw):
        mesh = raw["mesh"]
        self.surface = mesh if isinstance(mesh, Surface) else None
        self.tets = raw.get("tets", mesh if isinstance(mesh, TetMesh) else None)
        self.report = _json.loads(raw["report"])
        self.fem_ready = raw["fem_ready"]
        self.messages = list(raw["messages"])

    def to_json(self, indent=2):
        """The report as JSON text, as the command line writes it."""
        return _json.dumps(self.report, indent=indent)

    def __repr__(self):
        made = self.surface if self.surface is not None else self.tets
        ready = "" if self.fem_ready is None else f", fem_ready={self.fem_ready}"
        return f"<meshprep.Result: {made!r}{ready}>"


def _judged(raw, needs_verdict=True):
    result = Result(raw)
    if needs_verdict and result.fem_ready is False:
        failed = [c["check"] for c in result.report.get("thresholds", []) if not c.get("ok", True)]
        error = NotReadyError("not FEM-ready" + (": the tets fail " + ", ".join(failed) if failed else "")
                              + "; the result is in .result")
        error.result = result
        error.report = result.report
        raise error
    return result


def simplify(surface, *, progress=None, cancel=None, **keywords):
    return Result(_meshprep._simplify(surface, progress, cancel, keywords))


def smooth(surface, *, progress=None, cancel=None, **keywords):
    return Result(_meshprep._smooth(surface, progress, cancel, keywords))


def enhance(surface, reference=None, *, progress=None, cancel=None, **keywords):
    return Result(_meshprep._enhance(surface, reference, progress, cancel, keywords))


def repair(surface, *, cancel=None, **keywords):
    return Result(_meshprep._repair(surface, cancel, keywords))


def reconstruct(points, *, progress=None, cancel=None, **keywords):
    return Result(_meshprep._reconstruct(points, progress, cancel, keywords))


def check(surface):
    """The FEM readiness of a surface (closed, manifold, oriented, no self-intersections)."""
    return Result(_meshprep._check(surface))


def quality(mesh, reference=None, **keywords):
    return Result(_meshprep._quality(mesh, reference, keywords))


def tetrahedralize(surface, *, progress=None, cancel=None, **keywords):
    return _judged(_meshprep._tetrahedralize(surface, progress, cancel, keywords))


def improve(tets, reference=None, *, progress=None, cancel=None, **keywords):
    return _judged(_meshprep._improve(tets, reference, progress, cancel, keywords))


def pipeline(input, outdir=None, config=None, *, progress=None, cancel=None, **sections):
    raw = _meshprep._pipeline(input, outdir, config, progress, cancel, sections)
    return _judged(raw, needs_verdict=raw.pop("tetrahedralized"))


for _name, _doc in _meshprep._docs.items():
    globals()[_name].__doc__ = _doc


def _surface_from_meshio(mesh):
    """A Surface from a meshio.Mesh's points and triangle cells."""
    import numpy
    faces = [block.data for block in mesh.cells if block.type == "triangle"]
    if not faces:
        raise InputError("the meshio mesh has no triangle cells")
    return Surface(numpy.ascontiguousarray(mesh.points[:, :3], dtype=numpy.float64), numpy.concatenate(faces))


def _surface_to_meshio(self):
    """A meshio.Mesh of the triangles (copies the arrays: meshio may change them)."""
    import meshio
    return meshio.Mesh(self.points.copy(), [("triangle", self.faces.astype("int64"))])


def _tets_from_meshio(mesh):
    """A TetMesh from a meshio.Mesh's tetra cells (its boundary: the tets' own)."""
    import numpy
    tets = [block.data for block in mesh.cells if block.type == "tetra"]
    if not tets:
        raise InputError("the meshio mesh has no tetra cells")
    return TetMesh(numpy.ascontiguousarray(mesh.points[:, :3], dtype=numpy.float64), numpy.concatenate(tets))


def _tets_to_meshio(self):
    """A meshio.Mesh of the tets and the boundary triangles (copies the arrays)."""
    import meshio
    return meshio.Mesh(self.points.copy(), [("tetra", self.tets.astype("int64")),
                                            ("triangle", self.boundary_faces.astype("int64"))])


Surface.from_meshio = staticmethod(_surface_from_meshio)
Surface.to_meshio = _surface_to_meshio
TetMesh.from_meshio = staticmethod(_tets_from_meshio)
TetMesh.to_meshio = _tets_to_meshio
