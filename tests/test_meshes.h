#pragma once
// Procedural meshes for the tests: each is exact, small and has known analytic properties.

#include "meshprep/core/mesh.h"

namespace meshprep::test {

/// Regular tetrahedron with edge length `edge`, outward orientation. Volume edge^3 / (6 sqrt 2).
TriangleSoup regular_tetrahedron(double edge = 1.0);

/// Axis-aligned cube [0,s]^3, 12 triangles, outward orientation. Volume s^3.
TriangleSoup cube(double s = 1.0);

/// Icosahedron subdivided `levels` times (1-to-4) and projected on the sphere of radius r.
TriangleSoup icosphere(int levels, double r = 1.0);

/// Torus with major radius R, minor radius r, n x m quads split into triangles (genus 1).
TriangleSoup torus(int n, int m, double R = 2.0, double r = 0.5);

/// Flat n x n grid of unit-square cells split into triangles in the plane z = z0 (open, one boundary loop).
TriangleSoup grid(int n, double z0 = 0.0);

/// The surface of the cube [0, n]^3: n x n unit cells per side, two triangles each, points on edges
/// and corners shared by the sides, faces oriented outwards (closed, genus 0).
TriangleSoup subdivided_cube(int n);

/// `soup` translated by t.
TriangleSoup translated(TriangleSoup soup, const Vec3& t);

/// Concatenation of two soups (indices of b shifted).
TriangleSoup merged(const TriangleSoup& a, const TriangleSoup& b);

}  // namespace meshprep::test
