#!/usr/bin/env python3
"""Writes seeded dirty triangle soups made from closed parts, for the repair bench (issue 48, item 5).

Usage: dirty_cases.py OUT_DIR [--count N] [--seed S] [--sources FILE_OR_DIR ...] [--quick]

  OUT_DIR     created if missing; gets NAME.off per case (binary NAME.stl for the soups whose every
              face has its own corners: 'unwelded', and 'mixed' when unwelded is one of its steps)
              and manifest.json, a list of {"name", "kind", "seed", "sources", "params", "faces", "file"}
  --count N   number of cases (default 120), spread evenly over the kinds (case i has kind i mod 11)
  --seed S    the run's seed (default 48); case i draws from random.Random(S * 1000003 + i) only
  --sources   closed triangle meshes (binary or ASCII STL, OFF) or folders of them (their .stl and
              .off files); default: the bundled tests/data/example004.stl, tests/data/handle.off,
              examples/data/fandisk.off, examples/data/femur.off and, when the folder exists beside
              the clone, every part of ../shared/data/cad (a basename seen before is skipped)
  --quick     two cases of each kind (22) from the bundled meshes only, whatever --count and --sources say

Case NAME is KIND-III-SOURCE (III the case index, SOURCE the first source's basename). The sources
are cycled (case i takes source i mod n; 'union' cycles over the CAD parts, the STL sources when
there are four or more). Every length is a fraction of the source's bounding-box diagonal (the
params' "*_rel" values). The kinds:

  overlap            the part and a copy of it rotated at random about the bbox centre and shifted
                     by 10-40 % of the diagonal; the copies' surfaces cross (checked; drawn again
                     if not). Shift directions have each axis weighted by the part's bbox extent
  union              2-4 different parts, each scaled to 70-130 % of the first one's diagonal,
                     rotated at random and centred 5-30 % of it from the first one's centre, each
                     crossing the ones before it (checked; drawn again if not)
  unwelded           every face with its own three corners, each coordinate moved by up to
                     1e-9..1e-6 of the diagonal (log-uniform per case), written as float32 STL: a
                     corner that float32 rounding would put back moves by 1-3 float32 steps instead
  flipped            a connected patch of 1-10 % of the faces reversed (less than half its component)
  deleted            1-5 holes, each a connected patch of 1-20 faces removed, apart from each other
  tjunction          1-10 faces split in two at the midpoint of an edge whose neighbour face is not
  duplicate          1-5 % of the faces listed twice (appended), about half of them reversed
  internal           a flat disc of 48 triangles (16-gon, two rings) strictly inside the solid: its
                     radius is 90 % of its centre's distance to the surface, the centre the middle of
                     the longest inside stretch of six random lines through the bbox's middle half
  fin                1-5 extra triangles on manifold edges, their tip pushed out along the two
                     faces' mean normal (0.2-3 % of the diagonal), crossing nothing (checked)
  tiny_intersection  1-4 vertices pushed along their normal (inwards or outwards) through the face
                     that this line meets first among those sharing no vertex with their 1-ring,
                     ending 1e-4..1e-3 of the diagonal past it, and a moved face crosses it
                     (checked). The depth past the face is tiny; the push is the gap to that face
                     plus the depth ("gap_rel"): the smallest gaps of up to 1000 sampled vertices
                     are taken (within 5 % of the diagonal when there are enough, else 60 %), but a
                     closed part has no face that near: 2-10 % of the diagonal on the bundled
                     meshes, so the pushed vertex makes a thin spike across the solid or a gap
  mixed              three different kinds of the above but union applied in sequence (unwelded last)

Standard library only; the same arguments give the same bytes on any machine: only random.Random's
uniform draws, + - * / and sqrt make coordinates (rotations from quaternions, the disc's circle from
a table), numbers are written with repr. Each case's params hold a "check" of the defect (border,
non-manifold, badly oriented edges, duplicate faces, crossings found); the script stops if a case
lacks its defect. It ends with one line per kind: cases written and the kind's checked figures.
"""
import argparse
import json
import math
import os
import random
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
BUNDLED = [
    os.path.join(ROOT, "tests", "data", "example004.stl"),
    os.path.join(ROOT, "tests", "data", "handle.off"),
    os.path.join(ROOT, "examples", "data", "fandisk.off"),
    os.path.join(ROOT, "examples", "data", "femur.off"),
]
CAD = os.path.join(ROOT, "..", "shared", "data", "cad")
MAX_FACES = 400000  # per case
SEED_STRIDE = 1000003
ATTEMPTS = 300  # placements tried for overlap and union (a sparse part crosses its copy rarely)


# ---- readers: (points, triangles) of a closed mesh --------------------------------------------

def weld(corners):
    """Triangles of corner triples, equal coordinates (exactly) made one vertex; faces that lose
    a corner to the welding are dropped."""
    index, pts, tris = {}, [], []
    for i in range(0, len(corners), 3):
        ids = []
        for c in corners[i:i + 3]:
            if c not in index:
                index[c] = len(pts)
                pts.append(c)
            ids.append(index[c])
        if len(set(ids)) == 3:
            tris.append(tuple(ids))
    return pts, tris


def read_stl(path):
    with open(path, "rb") as f:
        data = f.read()
    if len(data) >= 84 and 84 + 50 * struct.unpack_from("<I", data, 80)[0] == len(data):
        corners = []
        for i in range(struct.unpack_from("<I", data, 80)[0]):
            v = struct.unpack_from("<12f", data, 84 + 50 * i)
            corners += [v[3:6], v[6:9], v[9:12]]
        return weld(corners)
    corners = []
    for line in data.decode("ascii", "replace").splitlines():
        words = line.split()
        if len(words) == 4 and words[0] == "vertex":
            corners.append(tuple(float(w) for w in words[1:]))
    return weld(corners)


def read_off(path):
    with open(path) as f:
        lines = [ln.split("#", 1)[0].split() for ln in f]
    lines = [ln for ln in lines if ln]
    head = lines[0]
    if head[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    rest = lines[1:]
    counts = head[1:] if len(head) > 1 else rest.pop(0)
    nv, nf = int(counts[0]), int(counts[1])
    pts = [tuple(float(w) for w in ln[:3]) for ln in rest[:nv]]
    tris = []
    for ln in rest[nv:nv + nf]:
        ids = [int(w) for w in ln[1:1 + int(ln[0])]]
        tris += [(ids[0], ids[k], ids[k + 1]) for k in range(1, len(ids) - 1)]
    return pts, [t for t in tris if len(set(t)) == 3]


def read_mesh(path):
    """The mesh, every face turned over when its signed volume is negative (outward normals)."""
    pts, tris = read_stl(path) if path.lower().endswith(".stl") else read_off(path)
    if signed_volume(pts, tris) < 0:
        tris = [(a, c, b) for a, b, c in tris]
    return pts, tris


# ---- writers ------------------------------------------------------------------------------------

def number(x):
    return repr(float(x))


def off_bytes(pts, tris):
    lines = ["OFF", f"{len(pts)} {len(tris)} 0"] + [" ".join(map(number, p)) for p in pts]
    lines += ["3 %d %d %d" % t for t in tris]
    return ("\n".join(lines) + "\n").encode()


def stl_bytes(pts, tris, title):
    out = [title.encode()[:80].ljust(80, b" "), struct.pack("<I", len(tris))]
    for t in tris:
        out.append(struct.pack("<12fH", 0, 0, 0, *pts[t[0]], *pts[t[1]], *pts[t[2]], 0))
    return b"".join(out)


# ---- vectors and transforms ------------------------------------------------------------------

def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def add(a, b):
    return (a[0] + b[0], a[1] + b[1], a[2] + b[2])


def mul(a, s):
    return (a[0] * s, a[1] * s, a[2] * s)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return mul(a, 1.0 / n) if n > 0 else None


def bbox(pts):
    return (tuple(min(p[k] for p in pts) for k in range(3)), tuple(max(p[k] for p in pts) for k in range(3)))


def diagonal(pts):
    lo, hi = bbox(pts)
    return norm(sub(hi, lo))


def centre(pts):
    lo, hi = bbox(pts)
    return mul(add(lo, hi), 0.5)


def boxes_overlap(a, b):
    return all(a[0][k] <= b[1][k] and b[0][k] <= a[1][k] for k in range(3))


def random_direction(rng):
    while True:
        d = (rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        if 1e-4 < dot(d, d) <= 1:
            return unit(d)


def spread_direction(rng, pts):
    """A random direction with each axis weighted by the bbox's extent along it (a flat part is
    mostly shifted within its plane)."""
    lo, hi = bbox(pts)
    while True:
        d = unit(tuple(c * (hi[k] - lo[k]) for k, c in enumerate(random_direction(rng))))
        if d is not None:
            return d


def random_rotation(rng):
    """A uniformly random rotation: (3x3 matrix rows, unit quaternion w x y z with w >= 0)."""
    while True:
        q = [rng.uniform(-1, 1) for _ in range(4)]
        n2 = sum(c * c for c in q)
        if 1e-4 < n2 <= 1:
            break
    n = math.sqrt(n2)
    w, x, y, z = (c / n for c in q)
    if w < 0:
        w, x, y, z = -w, -x, -y, -z
    m = ((1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)),
         (2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)),
         (2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)))
    return m, (w, x, y, z)


def angle_deg(quat):
    """The rotation angle, for the manifest only (rounded: acos may differ by an ulp across libms)."""
    return round(math.degrees(2 * math.acos(min(1.0, quat[0]))), 3)


def transformed(pts, m, about, s, to):
    """Each point p -> to + s * m (p - about)."""
    out = []
    for p in pts:
        d = sub(p, about)
        out.append((to[0] + s * dot(m[0], d), to[1] + s * dot(m[1], d), to[2] + s * dot(m[2], d)))
    return out


def rounded(v, digits=6):
    """A parameter for the manifest (drawn numbers are exact; derived ones are rounded)."""
    if isinstance(v, float):
        return float("%.*g" % (digits, v))
    if isinstance(v, (list, tuple)):
        return [rounded(x, digits) for x in v]
    return v


# ---- mesh figures ---------------------------------------------------------------------------

def signed_volume(pts, tris):
    return sum(dot(pts[a], cross(pts[b], pts[c])) for a, b, c in tris) / 6


def face_normal(pts, t):
    """Unnormalised (twice the area)."""
    a = pts[t[0]]
    return cross(sub(pts[t[1]], a), sub(pts[t[2]], a))


def edge_faces(tris):
    """Undirected edge (lo, hi) -> faces, in face order."""
    ef = {}
    for f, (a, b, c) in enumerate(tris):
        for u, v in ((a, b), (b, c), (c, a)):
            ef.setdefault((u, v) if u < v else (v, u), []).append(f)
    return ef


def vertex_faces(n, tris):
    vf = [[] for _ in range(n)]
    for f, t in enumerate(tris):
        for v in t:
            vf[v].append(f)
    return vf


def vertex_normals(pts, tris):
    vn = [(0.0, 0.0, 0.0)] * len(pts)
    for t in tris:
        n = face_normal(pts, t)
        for v in t:
            vn[v] = add(vn[v], n)
    return [unit(n) for n in vn]


def stats(pts, tris):
    """Border, non-manifold and badly oriented (both faces the same way round) edges, duplicate
    faces (same corner set), of the mesh as written (vertices by index; an STL's corners welded
    exactly first, as a reader does)."""
    ef = edge_faces(tris)
    directed = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            directed[(u, v)] = directed.get((u, v), 0) + 1
    seen, dups = {}, 0
    for t in tris:
        k = tuple(sorted(t))
        dups += k in seen
        seen[k] = None
    return {
        "border_edges": sum(len(fs) == 1 for fs in ef.values()),
        "non_manifold_edges": sum(len(fs) > 2 for fs in ef.values()),
        "misoriented_edges": sum(len(fs) == 2 and directed.get(e, 0) != 1 for e, fs in ef.items()),
        "duplicate_faces": dups,
    }


def components(tris, ef):
    """Face -> component id, and the components' sizes (faces joined across any edge)."""
    comp = [-1] * len(tris)
    sizes = []
    for s in range(len(tris)):
        if comp[s] >= 0:
            continue
        comp[s] = len(sizes)
        stack, n = [s], 0
        while stack:
            f = stack.pop()
            n += 1
            for g in neighbours(tris, ef, f):
                if comp[g] < 0:
                    comp[g] = comp[s]
                    stack.append(g)
        sizes.append(n)
    return comp, sizes


def neighbours(tris, ef, f):
    a, b, c = tris[f]
    out = []
    for u, v in ((a, b), (b, c), (c, a)):
        for g in ef[(u, v) if u < v else (v, u)]:
            if g != f:
                out.append(g)
    return out


def grow_patch(rng, tris, ef, seed, size, blocked=None):
    """A connected set of up to `size` faces from `seed`, grown by adding a random face of the
    frontier each step (faces in `blocked` are never taken). Returns the faces in order."""
    blocked = blocked or {}
    taken, order, frontier = {seed: None}, [seed], []
    for g in neighbours(tris, ef, seed):
        if g not in blocked and g not in taken:
            frontier.append(g)
    while len(order) < size and frontier:
        g = frontier.pop(rng.randrange(len(frontier)))
        if g in taken:
            continue
        taken[g] = None
        order.append(g)
        for h in neighbours(tris, ef, g):
            if h not in blocked and h not in taken:
                frontier.append(h)
    return order


# ---- geometric queries ------------------------------------------------------------------------

def line_triangle(p, d, a, b, c):
    """The parameter t of the line p + t d where it meets the triangle abc (any t), or None
    (Moller-Trumbore; a line in the triangle's plane counts as missing)."""
    e1, e2 = sub(b, a), sub(c, a)
    h = cross(d, e2)
    det = dot(e1, h)
    if det == 0:
        return None
    inv = 1.0 / det
    s = sub(p, a)
    u = dot(s, h) * inv
    if u < 0 or u > 1:
        return None
    qv = cross(s, e1)
    v = dot(d, qv) * inv
    if v < 0 or u + v > 1:
        return None
    return dot(e2, qv) * inv


def segment_triangle(p, q, a, b, c):
    """The parameter t in [0, 1] where the segment p-q meets the triangle abc, or None."""
    t = line_triangle(p, sub(q, p), a, b, c)
    return t if t is not None and 0 <= t <= 1 else None


def triangles_cross(t1, t2):
    """Whether an edge of one triangle (3 points each) passes through the other."""
    for x, y in ((t1, t2), (t2, t1)):
        for i in range(3):
            if segment_triangle(x[i], x[(i + 1) % 3], *y) is not None:
                return True
    return False


def closest_on_triangle(p, a, b, c):
    """The point of the triangle abc closest to p (Ericson, Real-Time Collision Detection 5.1.5)."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2 = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2 <= 0:
        return a
    bp = sub(p, b)
    d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3:
        return b
    vc = d1 * d4 - d3 * d2
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        return add(a, mul(ab, d1 / (d1 - d3)))
    cp = sub(p, c)
    d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6:
        return c
    vb = d5 * d2 - d1 * d6
    if vb <= 0 and d2 >= 0 and d6 <= 0:
        return add(a, mul(ac, d2 / (d2 - d6)))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        return add(b, mul(sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))))
    denom = 1.0 / (va + vb + vc)
    return add(a, add(mul(ab, vb * denom), mul(ac, vc * denom)))


def distance_to_surface(p, pts, tris):
    best = None
    for a, b, c in tris:
        d = norm(sub(p, closest_on_triangle(p, pts[a], pts[b], pts[c])))
        best = d if best is None or d < best else best
    return best


class Grid:
    """Faces of a mesh binned by their bounding boxes in a uniform grid of about 2 F^(1/3) cells
    along the diagonal; faces spanning more than 512 cells are kept in a list every query sees."""

    def __init__(self, pts, tris):
        self.pts, self.tris = pts, tris
        used = [pts[v] for t in tris for v in t]
        self.lo, hi = bbox(used)
        n = 1
        while n * n * n < len(tris):
            n += 1
        self.cell = max(norm(sub(hi, self.lo)) / max(4, min(64, 2 * n)), 1e-300)
        self.cells, self.big = {}, []
        for f, t in enumerate(tris):
            lo, hi = bbox([pts[v] for v in t])
            a, b = self.key(lo), self.key(hi)
            if (b[0] - a[0] + 1) * (b[1] - a[1] + 1) * (b[2] - a[2] + 1) > 512:
                self.big.append(f)
                continue
            for i in range(a[0], b[0] + 1):
                for j in range(a[1], b[1] + 1):
                    for k in range(a[2], b[2] + 1):
                        self.cells.setdefault((i, j, k), []).append(f)

    def key(self, p):
        return tuple(int(math.floor((p[k] - self.lo[k]) / self.cell)) for k in range(3))

    def faces_in_box(self, lo, hi):
        a, b = self.key(lo), self.key(hi)
        out = dict.fromkeys(self.big)
        for i in range(a[0], b[0] + 1):
            for j in range(a[1], b[1] + 1):
                for k in range(a[2], b[2] + 1):
                    for f in self.cells.get((i, j, k), ()):
                        out[f] = None
        return list(out)

    def faces_along(self, p, d, length):
        """Faces in the cells that the segment p, p + length d passes (sampled at cell / 4)."""
        out = dict.fromkeys(self.big)
        steps = int(length / (self.cell / 4)) + 1
        for s in range(steps + 1):
            for f in self.cells.get(self.key(add(p, mul(d, length * s / steps))), ()):
                out[f] = None
        return list(out)


def unique_edges(tris):
    edges = {}
    for a, b, c in tris:
        for u, v in ((a, b), (b, c), (c, a)):
            edges[(u, v) if u < v else (v, u)] = None
    return list(edges)


def edges_cross(pts_a, tris_a, grid_a, pts_b, tris_b):
    """Whether an edge of mesh b passes through a face of mesh a (the first such pair, or None)."""
    box_a = bbox([pts_a[v] for t in tris_a for v in t])
    for u, v in unique_edges(tris_b):
        p, q = pts_b[u], pts_b[v]
        lo = tuple(min(p[k], q[k]) for k in range(3))
        hi = tuple(max(p[k], q[k]) for k in range(3))
        if not boxes_overlap((lo, hi), box_a):
            continue
        for f in grid_a.faces_in_box(lo, hi):
            a, b, c = tris_a[f]
            if segment_triangle(p, q, pts_a[a], pts_a[b], pts_a[c]) is not None:
                return (u, v), f
    return None


def surfaces_cross(pts_a, tris_a, pts_b, tris_b, grid_a=None):
    """Whether the two meshes' surfaces cross: an edge of one through a face of the other."""
    if not boxes_overlap(bbox(pts_a), bbox(pts_b)):
        return False
    if edges_cross(pts_a, tris_a, grid_a or Grid(pts_a, tris_a), pts_b, tris_b):
        return True
    return edges_cross(pts_b, tris_b, Grid(pts_b, tris_b), pts_a, tris_a) is not None


def joined(meshes):
    pts, tris = [], []
    for p, t in meshes:
        off = len(pts)
        pts += p
        tris += [(a + off, b + off, c + off) for a, b, c in t]
    return pts, tris


# ---- the defect kinds: (rng, sources, diag) -> (points, triangles, params) -------------------

def overlap(rng, sources, diag):
    pts, tris = sources[0]
    about = centre(pts)
    grid = Grid(pts, tris)
    for attempt in range(1, ATTEMPTS + 1):
        m, quat = random_rotation(rng)
        shift_rel = rng.uniform(0.10, 0.40)
        direction = spread_direction(rng, pts)
        copy = transformed(pts, m, about, 1.0, add(about, mul(direction, shift_rel * diag)))
        if surfaces_cross(pts, tris, copy, tris, grid):
            break
    else:
        raise RuntimeError("overlap: no crossing copy in %d attempts" % ATTEMPTS)
    out_pts, out_tris = joined([(pts, tris), (copy, tris)])
    return out_pts, out_tris, {
        "angle_deg": angle_deg(quat), "quaternion": rounded(quat), "shift_rel": shift_rel,
        "direction": rounded(direction), "attempts": attempt, "crossing": True}


def union(rng, sources, diag):
    base_pts, base_tris = sources[0]
    about = centre(base_pts)
    acc_pts, acc_tris = list(base_pts), list(base_tris)
    parts = []
    for pts, tris in sources[1:]:
        d = diagonal(pts)
        grid = Grid(acc_pts, acc_tris)
        for attempt in range(1, ATTEMPTS + 1):
            size_rel = rng.uniform(0.7, 1.3)
            m, quat = random_rotation(rng)
            offset_rel = rng.uniform(0.05, 0.30)
            direction = spread_direction(rng, base_pts)
            placed = transformed(pts, m, centre(pts), size_rel * diag / d,
                                 add(about, mul(direction, offset_rel * diag)))
            if surfaces_cross(acc_pts, acc_tris, placed, tris, grid):
                break
        else:
            raise RuntimeError("union: no crossing placement in %d attempts" % ATTEMPTS)
        acc_pts, acc_tris = joined([(acc_pts, acc_tris), (placed, tris)])
        parts.append({"diagonal_rel": size_rel, "angle_deg": angle_deg(quat), "quaternion": rounded(quat),
                      "offset_rel": offset_rel, "direction": rounded(direction), "attempts": attempt})
    return acc_pts, acc_tris, {"parts": parts, "crossing": True}


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def f32_step(x, steps):
    """x (a float32 value) moved by `steps` float32 spacings (negative: down)."""
    for _ in range(abs(steps)):
        bits = struct.unpack("<I", struct.pack("<f", x))[0]
        if x == 0:
            bits = 1 if steps > 0 else 0x80000001
        elif (x > 0) == (steps > 0):
            bits += 1
        else:
            bits -= 1
        x = struct.unpack("<f", struct.pack("<I", bits))[0]
    return x


def unwelded(rng, sources, diag):
    pts, tris = sources[0]
    jitter_rel = rng.uniform(1.0, 10.0) * rng.choice((1e-9, 1e-8, 1e-7))
    jitter_rel = min(jitter_rel, 1e-6)
    amount = jitter_rel * diag
    out_pts, floor = [], 0
    for t in tris:
        for v in t:
            p = []
            for x in pts[v]:
                dx = rng.uniform(-1.0, 1.0) * amount
                x32, y32 = f32(x), f32(x + dx)
                if y32 == x32:  # lost to float32 rounding: one to three float32 steps instead
                    y32 = f32_step(x32, rng.choice((1, 2, 3)) * (1 if dx >= 0 else -1))
                    floor += 1
                p.append(y32)
            out_pts.append(tuple(p))
    out_tris = [(3 * i, 3 * i + 1, 3 * i + 2) for i in range(len(tris))]
    return out_pts, out_tris, {"jitter_rel": jitter_rel, "coordinates_moved_by_float32_steps": floor,
                               "distinct_corners": len(set(out_pts))}


def flipped(rng, sources, diag):
    pts, tris = sources[0]
    ef = edge_faces(tris)
    comp, sizes = components(tris, ef)
    fraction = rng.uniform(0.01, 0.10)
    want = max(1, int(round(fraction * len(tris))))
    big = max(range(len(sizes)), key=lambda c: (sizes[c], -c))
    want = min(want, max(1, (sizes[big] - 1) // 2))  # less than half a component: not its inversion
    for _ in range(100):
        seed = rng.randrange(len(tris))
        if sizes[comp[seed]] > 2 * want:
            break
    else:
        seed = min(f for f in range(len(tris)) if comp[f] == big)
    patch = grow_patch(rng, tris, ef, seed, want)
    flip = dict.fromkeys(patch)
    out = [(a, c, b) if f in flip else (a, b, c) for f, (a, b, c) in enumerate(tris)]
    return list(pts), out, {"fraction": fraction, "flipped_faces": len(patch)}


def deleted(rng, sources, diag):
    pts, tris = sources[0]
    ef = edge_faces(tris)
    comp, sizes = components(tris, ef)
    vf = vertex_faces(len(pts), tris)
    removed, blocked, holes = {}, {}, []
    for _ in range(rng.randint(1, 5)):
        size = rng.randint(1, 20)
        for _ in range(100):
            seed = rng.randrange(len(tris))
            if seed not in blocked and sizes[comp[seed]] > 2 * size:
                break
        else:
            continue
        patch = grow_patch(rng, tris, ef, seed, size, blocked)
        holes.append(len(patch))
        for f in patch:
            removed[f] = None
        for f in patch:  # the next hole keeps a vertex away from this one
            for v in tris[f]:
                for g in vf[v]:
                    blocked[g] = None
    if not holes:
        raise RuntimeError("deleted: no component is large enough")
    return list(pts), [t for f, t in enumerate(tris) if f not in removed], {"hole_faces": holes}


def tjunction(rng, sources, diag):
    pts, tris = sources[0]
    pts, tris = list(pts), list(tris)
    ef = edge_faces(tris)
    used, splits, want = {}, [], rng.randint(1, 10)
    for _ in range(100 * want):
        if len(splits) == want:
            break
        f = rng.randrange(len(tris))
        k = rng.randrange(3)
        a, b, c = tris[f][k], tris[f][(k + 1) % 3], tris[f][(k + 2) % 3]
        others = ef[(a, b) if a < b else (b, a)]
        if len(others) != 2 or f in used or any(g in used for g in others):
            continue
        for g in others:
            used[g] = None
        m = len(pts)
        pts.append(mul(add(pts[a], pts[b]), 0.5))
        splits.append((f, (a, m, c), (m, b, c)))
    out = []
    split = {f: (t1, t2) for f, t1, t2 in splits}
    for f, t in enumerate(tris):
        out += split[f] if f in split else [t]
    return pts, out, {"split_faces": len(splits)}


def duplicate(rng, sources, diag):
    pts, tris = sources[0]
    fraction = rng.uniform(0.01, 0.05)
    n = max(1, int(round(fraction * len(tris))))
    picked = rng.sample(range(len(tris)), n)
    flips = [rng.random() < 0.5 for _ in picked]
    if n >= 2 and all(flips) or n >= 2 and not any(flips):
        flips[0] = not flips[0]
    extra = [(a, c, b) if flip else (a, b, c) for (a, b, c), flip in zip((tris[f] for f in picked), flips)]
    return list(pts), list(tris) + extra, {"fraction": fraction, "duplicated": n, "reversed": sum(flips)}


# cos and sin of k * 22.5 degrees, k = 0..15, from a table (no libm: the same bits everywhere)
_C = (1.0, 0.9238795325112867, 0.7071067811865476, 0.3826834323650898, 0.0)
_COS = [(_C[k] if k <= 4 else -_C[8 - k]) if k <= 8 else (-_C[k - 8] if k <= 12 else _C[16 - k]) for k in range(16)]
CIRCLE = [(_COS[k], _COS[(k - 4) % 16]) for k in range(16)]


def internal(rng, sources, diag):
    pts, tris = sources[0]
    lo, hi = bbox(pts)
    stretches, lines = [], 0  # (length, middle point) of the inside parts of random lines
    for attempt in range(60):
        if lines == 6:
            break
        q = add(centre(pts), tuple((hi[k] - lo[k]) * rng.uniform(-0.25, 0.25) for k in range(3)))
        d = random_direction(rng)
        hits = sorted(t for t in (line_triangle(q, d, pts[a], pts[b], pts[c]) for a, b, c in tris)
                      if t is not None)
        if not hits or len(hits) % 2:
            continue  # a hit on an edge counted twice or once: no parity to trust
        lines += 1
        for i in range(0, len(hits), 2):
            stretches.append((hits[i + 1] - hits[i], add(q, mul(d, (hits[i] + hits[i + 1]) / 2))))
    stretches.sort(key=lambda s: -s[0])
    best = None
    for _, p in stretches[:3]:
        r = distance_to_surface(p, pts, tris)
        if best is None or r > best[0]:
            best = (r, p)
    if best is None or best[0] <= 0:
        raise RuntimeError("internal: no inside point found")
    radius, c = 0.9 * best[0], best[1]
    n = random_direction(rng)
    helper = (1.0, 0.0, 0.0) if abs(n[0]) < 0.6 else (0.0, 1.0, 0.0)
    u = unit(cross(n, helper))
    v = cross(n, u)
    disc = [c]
    for ring in (0.5, 1.0):
        for cs, sn in CIRCLE:
            disc.append(add(c, add(mul(u, ring * radius * cs), mul(v, ring * radius * sn))))
    dt = []
    for k in range(16):
        k1 = (k + 1) % 16
        dt.append((0, 1 + k, 1 + k1))
        dt += [(1 + k, 17 + k, 17 + k1), (1 + k, 17 + k1, 1 + k1)]
    out_pts, out_tris = joined([(pts, tris), (disc, dt)])
    return out_pts, out_tris, {"radius_rel": radius / diag, "centre_depth_rel": best[0] / diag,
                               "normal": rounded(n), "disc_faces": len(dt)}


def fin(rng, sources, diag):
    pts, tris = sources[0]
    pts, tris = list(pts), list(tris)
    ef = edge_faces(tris)
    grid = Grid(pts, tris)
    want, fins, used = rng.randint(1, 5), [], {}
    for _ in range(200 * want):
        if len(fins) == want:
            break
        f = rng.randrange(len(tris))
        k = rng.randrange(3)
        a, b = tris[f][k], tris[f][(k + 1) % 3]
        e = (a, b) if a < b else (b, a)
        if len(ef.get(e, ())) != 2 or e in used:
            continue
        n1, n2 = (unit(face_normal(pts, tris[g])) for g in ef[e])
        if n1 is None or n2 is None or unit(add(n1, n2)) is None:
            continue
        out = unit(add(n1, n2))
        length = norm(sub(pts[a], pts[b]))
        height_rel = min(max(length / diag * rng.uniform(0.5, 1.0), 0.002), 0.03)
        tip = add(mul(add(pts[a], pts[b]), 0.5), mul(out, height_rel * diag))
        lo = tuple(min(pts[a][i], pts[b][i], tip[i]) for i in range(3))
        hi = tuple(max(pts[a][i], pts[b][i], tip[i]) for i in range(3))
        fin_tri = (pts[a], pts[b], tip)
        if any(triangles_cross(fin_tri, tuple(pts[v] for v in tris[g])) for g in grid.faces_in_box(lo, hi)
               if a not in tris[g] and b not in tris[g]):
            continue
        used[e] = None
        pts.append(tip)
        fins.append(height_rel)
        tris.append((a, b, len(pts) - 1) if rng.random() < 0.5 else (b, a, len(pts) - 1))
    if not fins:
        raise RuntimeError("fin: no edge takes a fin")
    return pts, tris, {"fin_heights_rel": rounded(fins)}


def tiny_intersection(rng, sources, diag):
    pts, tris = sources[0]
    pts = list(pts)
    vf = vertex_faces(len(pts), tris)
    vn = vertex_normals(pts, tris)
    grid = Grid(pts, tris)
    used_vertices = [v for v in range(len(pts)) if vf[v] and vn[v] is not None]
    sample = rng.sample(used_vertices, min(len(used_vertices), 1000))
    want = rng.randint(1, 4)
    for reach_rel in (0.05, 0.6):  # the nearer faces when there are enough of them
        reach = reach_rel * diag
        candidates = []
        for v in sample:
            ring = {w for g in vf[v] for w in tris[g]}
            for sign in (1.0, -1.0):
                d = mul(vn[v], sign)
                best = None
                for g in grid.faces_along(pts[v], d, reach):
                    a, b, c = tris[g]
                    if a in ring or b in ring or c in ring:
                        continue
                    t = segment_triangle(pts[v], add(pts[v], mul(d, reach)), pts[a], pts[b], pts[c])
                    if t is not None and t > 0 and (best is None or t < best[0]):
                        best = (t * reach, g)
                if best:
                    candidates.append((best[0], v, sign, best[1]))
        if len(candidates) >= 4 * want:
            break
    candidates.sort()
    pushes, touched = [], {}
    for gap, v, sign, g in candidates:
        if len(pushes) == want:
            break
        ring = {w for h in vf[v] for w in tris[h]}
        if any(w in touched for w in ring) or any(w in touched for w in tris[g]):
            continue
        depth_rel = rng.uniform(1e-4, 1e-3)
        d = mul(vn[v], sign)
        moved = add(pts[v], mul(d, gap + depth_rel * diag))
        target = tuple(pts[w] for w in tris[g])
        trial = list(pts)
        trial[v] = moved
        if not any(triangles_cross(tuple(trial[w] for w in tris[h]), target) for h in vf[v]):
            continue
        pts[v] = moved
        for w in list(ring) + list(tris[g]):
            touched[w] = None
        pushes.append({"gap_rel": rounded(gap / diag), "depth_rel": depth_rel,
                       "direction": "out" if sign > 0 else "in"})
    if not pushes:
        raise RuntimeError("tiny_intersection: no vertex's normal meets a face within 60 % of the diagonal")
    return pts, list(tris), {"pushes": pushes, "crossing": True}


def mixed(rng, sources, diag):
    steps = rng.sample(MIXABLE, 3)
    if "unwelded" in steps:
        steps.remove("unwelded")
        steps.append("unwelded")
    mesh, record = sources[0], []
    for kind in steps:
        pts, tris, params = KINDS[kind](rng, [mesh], diag)
        mesh = (pts, tris)
        if kind != "unwelded":  # the soup keeps the defects before it, though not as topology
            params["check"] = stats(pts, tris)
            check(kind, params, params["check"])
        record.append({"kind": kind, "params": params})
    return mesh[0], mesh[1], {"steps": record}


KINDS = {
    "overlap": overlap, "union": union, "unwelded": unwelded, "flipped": flipped, "deleted": deleted,
    "tjunction": tjunction, "duplicate": duplicate, "internal": internal, "fin": fin,
    "tiny_intersection": tiny_intersection, "mixed": mixed,
}
MIXABLE = [k for k in KINDS if k not in ("union", "mixed")]

# the figure of stats() each kind must raise above zero (crossings are checked while generating)
EXPECTED = {
    "unwelded": "border_edges", "flipped": "misoriented_edges", "deleted": "border_edges",
    "tjunction": "border_edges", "duplicate": "duplicate_faces", "internal": "border_edges",
    "fin": "non_manifold_edges",
}


def check(kind, params, figures):
    if kind == "mixed":
        last = params["steps"][-1]
        check(last["kind"], last["params"], figures)  # mixed() checked each step after it ran
    elif kind in EXPECTED:
        if figures[EXPECTED[kind]] == 0:
            raise RuntimeError(f"{kind}: the case has no {EXPECTED[kind]}")
    elif not params.get("crossing"):
        raise RuntimeError(f"{kind}: no crossing recorded")


# ---- the cases --------------------------------------------------------------------------------

def source_files(args):
    if args.quick:
        paths = list(BUNDLED)
    elif args.sources:
        paths = []
        for s in args.sources:
            if os.path.isdir(s):
                paths += [os.path.join(s, n) for n in sorted(os.listdir(s)) if n.lower().endswith((".stl", ".off"))]
            else:
                paths.append(s)
    else:
        paths = list(BUNDLED)
        if os.path.isdir(CAD):
            paths += [os.path.join(CAD, n) for n in sorted(os.listdir(CAD)) if n.lower().endswith((".stl", ".off"))]
    seen, out = {}, []
    for p in paths:
        base = os.path.basename(p)
        if base not in seen:
            seen[base] = None
            out.append(p)
    return out


def stem(path):
    return os.path.splitext(os.path.basename(path))[0]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("out_dir")
    parser.add_argument("--count", type=int, default=120)
    parser.add_argument("--seed", type=int, default=48)
    parser.add_argument("--sources", nargs="+")
    parser.add_argument("--quick", action="store_true")
    args = parser.parse_args()
    paths = source_files(args)
    if not paths:
        sys.exit("dirty_cases.py: no source meshes")
    meshes = {}

    def mesh(path):
        if path not in meshes:
            meshes[path] = read_mesh(path)
        return meshes[path]

    stls = [p for p in paths if p.lower().endswith(".stl")]
    parts = [p for p in (stls if len(stls) >= 4 else paths) if len(mesh(p)[1]) <= MAX_FACES // 4]
    count = 2 * len(KINDS) if args.quick else args.count
    os.makedirs(args.out_dir, exist_ok=True)
    manifest, per_kind = [], {k: [] for k in KINDS}
    kinds = list(KINDS)
    for i in range(count):
        kind = kinds[i % len(kinds)]
        seed = args.seed * SEED_STRIDE + i
        rng = random.Random(seed)
        if kind == "union":
            if len(parts) < 2:
                sys.exit("dirty_cases.py: union needs two sources of at most %d faces" % (MAX_FACES // 4))
            first = parts[i % len(parts)]
            others = [p for p in parts if p != first]
            used = [first] + rng.sample(others, min(len(others), rng.randint(1, 3)))
        else:
            used = [paths[i % len(paths)]]
        sources = [mesh(p) for p in used]
        diag = diagonal(sources[0][0])
        pts, tris, params = KINDS[kind](rng, sources, diag)
        if len(tris) > MAX_FACES:
            sys.exit(f"dirty_cases.py: case {i} ({kind}) has {len(tris)} faces, more than {MAX_FACES}")
        soup = kind == "unwelded" or kind == "mixed" and params["steps"][-1]["kind"] == "unwelded"
        name = "%s-%03d-%s" % (kind, i, stem(used[0]))
        file = name + (".stl" if soup else ".off")
        data = stl_bytes(pts, tris, f"meshprep dirty case {name}") if soup else off_bytes(pts, tris)
        figures = stats(*weld([pts[v] for t in tris for v in t])) if soup else stats(pts, tris)
        check(kind, params, figures)
        params["check"] = figures
        with open(os.path.join(args.out_dir, file), "wb") as f:
            f.write(data)
        manifest.append({"name": name, "kind": kind, "seed": seed, "sources": [os.path.basename(p) for p in used],
                         "params": params, "faces": len(tris), "file": file})
        per_kind[kind].append(manifest[-1])
        print("%s: %d faces" % (name, len(tris)), file=sys.stderr, flush=True)
    with open(os.path.join(args.out_dir, "manifest.json"), "w") as f:
        json.dump(manifest, f, indent=1, sort_keys=True)
        f.write("\n")
    for kind, rows in per_kind.items():
        if not rows:
            continue
        faces = [c["faces"] for c in rows]
        if kind == "mixed":
            what = "each step's defect checked after it ran"
        elif kind in EXPECTED:
            values = [c["params"]["check"][EXPECTED[kind]] for c in rows]
            what = "%s > 0 in %d, total %d" % (EXPECTED[kind], sum(v > 0 for v in values), sum(values))
        else:
            what = "surfaces cross in %d" % sum(bool(c["params"].get("crossing")) for c in rows)
        print("%-18s %3d cases, %d-%d faces; %s" % (kind, len(rows), min(faces), max(faces), what))
    print("%d cases in %s" % (len(manifest), args.out_dir))


if __name__ == "__main__":
    main()
