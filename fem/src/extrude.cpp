#include "meshprep/fem/extrude.h"

#include "meshprep/core/errors.h"
#include "meshprep/quality/topology.h"

#include <algorithm>
#include <limits>
#include <map>

namespace meshprep {
namespace {

// The border of an oriented open surface as one closed chain of vertices: each border edge is
// used by one face, in that face's direction a -> b.
std::vector<std::uint32_t> boundary_loop(const TriangleSoup& s) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : s.triangles)
    for (int c = 0; c < 3; ++c) ++uses[std::minmax(t[c], t[(c + 1) % 3])];
  std::map<std::uint32_t, std::uint32_t> next;
  for (const Triangle& t : s.triangles)
    for (int c = 0; c < 3; ++c)
      if (uses[std::minmax(t[c], t[(c + 1) % 3])] == 1) next[t[c]] = t[(c + 1) % 3];
  std::vector<std::uint32_t> loop;
  const std::uint32_t first = next.begin()->first;
  std::uint32_t v = first;
  do {
    loop.push_back(v);
    v = next.at(v);
  } while (v != first && loop.size() <= next.size());
  if (v != first || loop.size() != next.size())
    throw InvalidInput("the surface's border is not a single simple loop (a boundary vertex is pinched)");
  return loop;
}

}  // namespace

SurfacePlc extrude_to_block(const TriangleSoup& surface, double depth) {
  if (!(depth > 0)) throw InvalidInput("the extrusion depth must be positive");
  const Topology topo = analyze_topology(surface);
  if (topo.closed) throw InvalidInput("the surface is already closed: there is nothing to extrude");
  if (!topo.oriented)
    throw InvalidInput("the surface must be manifold and consistently oriented to be extruded into a block");
  if (topo.boundary_loops != 1)
    throw InvalidInput("the surface has " + std::to_string(topo.boundary_loops) +
                       " boundary loops; a height field to extrude has exactly one");

  // Up: the coordinate axis nearest to the area-weighted mean normal. An axis keeps the base and
  // the side walls exactly planar in floating point (TetGen asserts on facets that are not).
  Vec3 mean_normal = Vec3::Zero();
  for (const Triangle& t : surface.triangles)
    mean_normal += (surface.points[t[1]] - surface.points[t[0]]).cross(surface.points[t[2]] - surface.points[t[0]]);
  if (mean_normal.norm() == 0) throw InvalidInput("the surface has no mean normal (zero area)");
  int axis = 0;
  mean_normal.cwiseAbs().maxCoeff(&axis);
  const Vec3 up = Vec3::Unit(axis) * (mean_normal[axis] > 0 ? 1.0 : -1.0);
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    const Vec3 n = (surface.points[t[1]] - surface.points[t[0]]).cross(surface.points[t[2]] - surface.points[t[0]]);
    if (!(n.dot(up) > 0))
      throw InvalidInput("face " + std::to_string(f) + " folds over: the surface is not a height field over the " +
                         std::string(1, "xyz"[axis]) + " axis, so it cannot be extruded into a block");
  }

  // Points: the referenced surface points, then one base point under each boundary vertex.
  SurfacePlc plc;
  std::vector<std::uint32_t> renumber(surface.points.size(), UINT32_MAX);
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : surface.triangles)
    for (auto v : t)
      if (renumber[v] == UINT32_MAX) {
        renumber[v] = static_cast<std::uint32_t>(plc.points.size());
        plc.points.push_back(surface.points[v]);
        lowest = std::min(lowest, surface.points[v].dot(up));
      }
  const double base_level = lowest - depth;
  for (const Triangle& t : surface.triangles) {
    plc.facets.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
    plc.tags.push_back(kTopTag);
  }
  const std::vector<std::uint32_t> loop = boundary_loop(surface);
  std::vector<std::uint32_t> below(loop.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = surface.points[loop[i]];
    below[i] = static_cast<std::uint32_t>(plc.points.size());
    Vec3 q = p;
    q[axis] = up[axis] * base_level;  // exactly on the base plane
    plc.points.push_back(q);
  }
  // Side walls: one vertical quad per border edge (planar: it contains the edge and `up`).
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::size_t j = (i + 1) % loop.size();
    plc.facets.push_back({renumber[loop[j]], renumber[loop[i]], below[i], below[j]});
    plc.tags.push_back(kSideTag);
  }
  // Base: the projected loop as one planar polygon, reversed so that it faces down.
  plc.facets.emplace_back(below.rbegin(), below.rend());
  plc.tags.push_back(kBaseTag);
  return plc;
}

}  // namespace meshprep
