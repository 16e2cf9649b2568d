#!/usr/bin/env python3
"""Writes the broken-mesh corpus of issue #9 into the current folder (see cli_corpus_test.sh).

Usage: broken_meshes.py

A mesh case NAME is written as NAME.off, NAME.obj, NAME-ascii.ply, NAME-binary.ply,
NAME-ascii.stl and NAME-binary.stl, or a subset of them: the topology cases in an indexed
format (OFF) and in binary STL, which merges equal corners (binary PLY instead for the cases STL
cannot hold, which need a vertex list); the offset sphere and the one face in all six. Damaged files (empty, truncated, NaN) are written in all six formats, headers lying about
their element counts in PLY (ASCII and binary) and OFF, and point sets (.xyz) with broken lines
for reconstruct and pipeline. All geometry is generated here: the cube and the two boxes come
from cli_meshes.py, the sphere is a subdivided octahedron.
"""
import math
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cli_meshes import P as CUBE_POINTS, T as CUBE_TRIANGLES, meshes as cli_meshes  # noqa: E402


def sphere(subdivisions=2):
    """A unit sphere: the octahedron, each triangle split in four `subdivisions` times."""
    pts = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
    tris = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]
    for _ in range(subdivisions):
        middle = {}

        def mid(a, b):
            key = (min(a, b), max(a, b))
            if key not in middle:
                p = [(pts[a][k] + pts[b][k]) / 2 for k in range(3)]
                r = math.sqrt(sum(c * c for c in p))
                middle[key] = len(pts)
                pts.append(tuple(c / r for c in p))
            return middle[key]

        split = []
        for a, b, c in tris:
            ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
            split += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        tris = split
    return [tuple(on_grid(c) for c in p) for p in pts], tris


def on_grid(c):
    """c rounded to a multiple of 2^-20: such numbers of magnitude up to 2 keep every bit when
    1e9 is added (the spacing of doubles near 1e9 is 2^-23), so the shifted mesh is an exact translate."""
    return round(c * 2**20) / 2**20


def shifted(mesh, offset):
    pts, tris = mesh
    return [tuple(c + o for c, o in zip(p, offset)) for p in pts], tris


def zero_area_cube():
    """The closed cube with the triangle (0, 2, 1) split at the midpoint m of the edge 0-1 and the
    sliver (0, m, 1) of zero area filling the gap: still closed, manifold and oriented."""
    m = len(CUBE_POINTS)
    tris = [t for t in CUBE_TRIANGLES if t != (0, 2, 1)] + [(0, 2, m), (m, 2, 1), (0, m, 1)]
    return CUBE_POINTS + [(0.5, 0.0, 0.0)], tris


TOPOLOGY = (".off", "-binary.stl")  # an indexed format, and STL, which merges equal corners
INDEXED = (".off", "-binary.ply")  # for the cases STL cannot hold


def mesh_cases():
    """name -> (points, triangles, file suffixes)."""
    two_tets = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1)]
    tet = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
    flipped = [tuple(reversed(t)) if i == 5 else t for i, t in enumerate(CUBE_TRIANGLES)]
    every = tuple(FORMATS)
    return {
        "sphere": (*sphere(), TOPOLOGY),  # the control: a good closed surface
        "hole": (CUBE_POINTS, CUBE_TRIANGLES[1:], TOPOLOGY),
        "flipped": (CUBE_POINTS, flipped, TOPOLOGY),
        "nonmanifold_edge": (*cli_meshes()["fin"], TOPOLOGY),
        "nonmanifold_vertex": (two_tets, tet + [(0, 5, 4), (0, 4, 6), (0, 6, 5), (4, 5, 6)], TOPOLOGY),
        "duplicate_face": (*cli_meshes()["duplicate"], TOPOLOGY),
        "zero_area": (*zero_area_cube(), TOPOLOGY),
        "repeated_corner": (CUBE_POINTS, CUBE_TRIANGLES + [(0, 0, 7)], INDEXED),
        "isolated_vertices": (CUBE_POINTS + [(0.5, 0.5, 0.5), (3.0, 3.0, 3.0)], CUBE_TRIANGLES, INDEXED),
        "self_intersecting": (*cli_meshes()["two_boxes"], TOPOLOGY),
        "touching": (CUBE_POINTS + [(x + 1, y, z) for (x, y, z) in CUBE_POINTS],
                     CUBE_TRIANGLES + [tuple(i + 8 for i in t) for t in CUBE_TRIANGLES], TOPOLOGY),
        "offset_1e9": (*shifted(sphere(), (1e9, 1e9, 1e9)), every),
        "one_face": ([(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [(0, 1, 2)], every),
    }


# ---- writers: bytes of a mesh in each format ---------------------------------------------------

def number(x):
    return repr(float(x))


def off_bytes(pts, tris, counts=None):
    nv, nf = counts or (len(pts), len(tris))
    lines = ["OFF", f"{nv} {nf} 0"] + [" ".join(map(number, p)) for p in pts]
    lines += ["3 %d %d %d" % t for t in tris]
    return ("\n".join(lines) + "\n").encode()


def obj_bytes(pts, tris):
    lines = ["v " + " ".join(map(number, p)) for p in pts] + ["f %d %d %d" % tuple(i + 1 for i in t) for t in tris]
    return ("\n".join(lines) + "\n").encode()


def ply_bytes(pts, tris, binary, counts=None):
    nv, nf = counts or (len(pts), len(tris))
    header = ("ply\nformat %s 1.0\nelement vertex %d\nproperty double x\nproperty double y\nproperty double z\n"
              "element face %d\nproperty list uchar int vertex_indices\nend_header\n"
              % ("binary_little_endian" if binary else "ascii", nv, nf)).encode()
    if binary:
        body = b"".join(struct.pack("<3d", *p) for p in pts) + b"".join(struct.pack("<B3i", 3, *t) for t in tris)
    else:
        body = ("".join(" ".join(map(number, p)) + "\n" for p in pts) + "".join("3 %d %d %d\n" % t for t in tris)).encode()
    return header + body


def stl_bytes(pts, tris, binary):
    if binary:
        out = b"corpus of broken meshes (meshprep tests)".ljust(80, b" ") + struct.pack("<I", len(tris))
        for t in tris:
            out += struct.pack("<3f", 0, 0, 0) + b"".join(struct.pack("<3f", *pts[i]) for i in t) + b"\0\0"
        return out
    text = "solid corpus\n"
    for t in tris:
        text += "facet normal 0 0 0\nouter loop\n"
        text += "".join("vertex " + " ".join(map(number, pts[i])) + "\n" for i in t)
        text += "endloop\nendfacet\n"
    return (text + "endsolid corpus\n").encode()


FORMATS = {  # file suffix -> writer
    ".off": lambda p, t: off_bytes(p, t),
    ".obj": lambda p, t: obj_bytes(p, t),
    "-ascii.ply": lambda p, t: ply_bytes(p, t, False),
    "-binary.ply": lambda p, t: ply_bytes(p, t, True),
    "-ascii.stl": lambda p, t: stl_bytes(p, t, False),
    "-binary.stl": lambda p, t: stl_bytes(p, t, True),
}


def truncated(suffix, data):
    """The file cut where its reader must notice: inside the vertex or facet data, or for OBJ
    (which announces no counts) after the second corner of its last face."""
    if suffix == ".obj":
        last = data.rstrip(b"\n").rsplit(b"\n", 1)[1]
        return data[: data.rindex(last) + len(last.rsplit(b" ", 1)[0])]
    return data[: len(data) * 3 // 5]


def damaged_files():
    """name -> bytes: empty, truncated, NaN and lying-count files in every format."""
    files = {}
    nan_points = [(float("nan"), 0.0, 0.0)] + CUBE_POINTS[1:]
    for suffix, write in FORMATS.items():
        files["empty" + suffix] = b""
        files["truncated" + suffix] = truncated(suffix, write(CUBE_POINTS, CUBE_TRIANGLES))
        files["nan" + suffix] = write(nan_points, CUBE_TRIANGLES)
    # Element counts that do not match the data: one more vertex than there is (the first face
    # line is then read as a vertex), one face fewer than there is (data left over), three
    # billion vertices (memory must not be reserved for them).
    n_v, n_f = len(CUBE_POINTS), len(CUBE_TRIANGLES)
    for kind, binary in (("ascii", False), ("binary", True)):
        files[f"lying_count_more-{kind}.ply"] = ply_bytes(CUBE_POINTS, CUBE_TRIANGLES, binary, (n_v + 1, n_f))
        files[f"lying_count_fewer-{kind}.ply"] = ply_bytes(CUBE_POINTS, CUBE_TRIANGLES, binary, (n_v, n_f - 1))
    files["lying_count_huge-binary.ply"] = ply_bytes(CUBE_POINTS, CUBE_TRIANGLES, True, (3 * 10**9, n_f))
    files["lying_count_more.off"] = off_bytes(CUBE_POINTS, CUBE_TRIANGLES, (n_v, n_f + 1))
    return files


def point_files():
    """The .xyz cases: a good height field and broken variants of it."""
    def height(i):
        x, y = math.fmod(0.5 + i * 0.7548776662466927, 1.0), math.fmod(0.5 + i * 0.5698402909980532, 1.0)
        return on_grid(x), on_grid(y), on_grid(0.2 * math.sin(3 * x) * y)

    good = [height(i) for i in range(200)]
    lines = [" ".join(map(number, p)) for p in good]
    text = lambda rows: ("\n".join(rows) + "\n").encode()
    return {
        "points.xyz": text(lines),
        "points_offset_1e9.xyz": text(" ".join(number(c + 1e9) for c in p) for p in good),
        "points_two_values.xyz": text(lines[:50] + ["0.5 0.5"] + lines[50:]),
        "points_word.xyz": text(lines[:50] + ["0.5 zero 0.5"] + lines[50:]),
        "points_nan.xyz": text(lines[:50] + ["0.5 nan 0.5"] + lines[50:]),
        "points_four_values.xyz": text(lines[:50] + ["0.5 0.5 0.5 0.5"] + lines[50:]),
        "points_too_few.xyz": text(lines[:5]),
        "points_truncated.xyz": text(lines[:100])[:-1] + b"\n" + lines[100].rsplit(" ", 1)[0].encode(),
        "points_empty.xyz": b"",
    }


def main():
    for name, (pts, tris, suffixes) in mesh_cases().items():
        for suffix in suffixes:
            with open(name + suffix, "wb") as f:
                f.write(FORMATS[suffix](pts, tris))
    for name, data in {**damaged_files(), **point_files()}.items():
        with open(name, "wb") as f:
            f.write(data)


if __name__ == "__main__":
    main()
