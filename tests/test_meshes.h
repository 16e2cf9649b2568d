#pragma once
// Procedural meshes for the tests: each is exact, small and has known analytic properties.

#include "meshprep/core/mesh.h"

namespace meshprep::test {

/// Regular tetrahedron with edge length `edge`, outward orientation. Volume edge^3 / (6 sqrt 2).
TriangleSoup regular_tetrahedron(double edge = 1.0);

/// Axis-aligned cube [0,s]^3, 12 triangles, outward orientation. Volume s^3.
TriangleSoup cube(double s = 1.0);

/// The axis-aligned box [lo, hi], twelve outward faces.
TriangleSoup box(const Vec3& lo, const Vec3& hi);

/// Icosahedron subdivided `levels` times (1-to-4) and projected on the sphere of radius r.
TriangleSoup icosphere(int levels, double r = 1.0);

/// icosphere(levels) with every vertex moved by up to `amplitude` along each axis (uniform,
/// std::mt19937(seed), drawn in sequence: the same sphere whatever the compiler) and put back on
/// the unit sphere: poor triangles on an exact sphere.
TriangleSoup jittered_icosphere(int levels, double amplitude, unsigned seed);

/// Torus with major radius R, minor radius r, n x m quads split into triangles (genus 1).
TriangleSoup torus(int n, int m, double R = 2.0, double r = 0.5);

/// Flat n x n grid of unit-square cells split into triangles in the plane z = z0 (open, one boundary loop).
TriangleSoup grid(int n, double z0 = 0.0);

/// The surface of the cube [0, n]^3: n x n unit cells per side, two triangles each, points on edges
/// and corners shared by the sides, faces oriented outwards (closed, genus 0).
TriangleSoup subdivided_cube(int n);

/// The regular polygon with `corners` corners on the unit circle (z = 0), fan-triangulated from
/// its first corner: corners - 2 long thin triangles that all have that corner.
TriangleSoup fan_triangulated_polygon(int corners);

/// A closed cylinder of radius 1 and height 1 whose caps are such fans (from the same corner) and
/// whose side is one ring of quads split in two: 4 corners - 4 faces.
TriangleSoup cylinder_with_fan_caps(int corners);

/// A closed wavy plate: two parallel sheets z = 0.3 sin 3x cos 2y (+ gap) over [0, 3]^2, n x n
/// squares each, closed by a rim. Coarse chords of one sheet pierce the other when the gap is
/// smaller than their sagitta.
TriangleSoup thin_wavy_plate(int n, double gap);

/// The unit cube whose top front edge (0,0,1)-(1,0,1) is split at its middle by a vertex pushed
/// `bulge` out along the diagonal (0, -1, 1): the face between that vertex and the edge's ends is a
/// cap, its angle at the vertex 180 degrees less about 4 bulge / sqrt 2 radians. Closed, outward.
TriangleSoup cube_with_cap(double bulge);

/// `soup` translated by t.
TriangleSoup translated(TriangleSoup soup, const Vec3& t);

/// Concatenation of two soups (indices of b shifted).
TriangleSoup merged(const TriangleSoup& a, const TriangleSoup& b);

}  // namespace meshprep::test
