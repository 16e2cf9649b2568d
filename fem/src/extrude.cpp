#include "meshprep/fem/extrude.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"
#include "meshprep/quality/height_field.h"
#include "meshprep/quality/topology.h"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

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

// The base: the surface's triangles projected onto the base plane (a height field projects to a
// triangulation of its footprint), reversed to face down, then coarsened by OpenMesh's decimater:
// halfedge collapses keep every vertex exactly in the plane, the border vertices are locked
// (the walls stand on them), no triangle may flip, and none may get thinner than an aspect ratio
// of 5. TetGen's own triangulation of the footprint as one polygon asserts on the nearly
// collinear corners of a simplified border (sscoutsegment; measured on the Jacksboro terrain),
// and the uncoarsened projection doubles the tets.
TriMesh coarse_base(const TriangleSoup& surface, const std::vector<std::uint32_t>& below, const SurfacePlc& plc) {
  TriMesh base;
  std::vector<TriMesh::VertexHandle> handle(surface.points.size());
  for (std::size_t v = 0; v < surface.points.size(); ++v)
    if (below[v] != UINT32_MAX) handle[v] = base.add_vertex(to_openmesh(plc.points[below[v]]));
  for (const Triangle& t : surface.triangles) base.add_face(handle[t[0]], handle[t[2]], handle[t[1]]);
  for (const auto v : base.vertices())
    if (base.is_boundary(v)) base.status(v).set_locked(true);
  base.update_face_normals();  // ModNormalFlipping compares against them
  using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
  Decimater decimater(base);
  OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle no_flips;
  OpenMesh::Decimater::ModAspectRatioT<TriMesh>::Handle shape;
  decimater.add(quadric);
  decimater.add(no_flips);
  decimater.add(shape);
  decimater.module(quadric).unset_max_err();
  decimater.module(shape).set_aspect_ratio(5.0f);
  decimater.initialize();
  decimater.decimate();
  base.garbage_collection();
  return base;
}

}  // namespace

SurfacePlc extrude_to_block(const TriangleSoup& surface, double depth) {
  if (!(depth > 0 && std::isfinite(depth))) throw InvalidInput("the extrusion depth must be positive and finite");
  const Topology topo = analyze_topology(surface);
  if (topo.closed) throw InvalidInput("the surface is already closed: there is nothing to extrude");
  if (!topo.oriented)
    throw InvalidInput("the surface must be manifold and consistently oriented to be extruded into a block");
  if (topo.boundary_loops != 1)
    throw InvalidInput("the surface has " + std::to_string(topo.boundary_loops) +
                       " boundary loops; a height field to extrude has exactly one");

  // Up: the coordinate axis nearest to the area-weighted mean normal. An axis keeps the base and
  // the side walls exactly planar in floating point (TetGen asserts on facets that are not).
  const std::optional<Vec3> mean_axis = mean_normal_axis(surface);
  if (!mean_axis) throw InvalidInput("the surface has no mean normal (zero area)");
  const Vec3 up = *mean_axis;
  int axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  if (const std::optional<std::size_t> f = first_fold(surface, up))
    throw InvalidInput("face " + std::to_string(*f) + " folds over: the surface is not a height field over the " +
                       std::string(1, "xyz"[axis]) + " axis, so it cannot be extruded into a block");

  // Points: the referenced surface points, then their projections onto the base plane.
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
  for (const Triangle& t : surface.triangles) plc.facets.push_back({renumber[t[0]], renumber[t[1]], renumber[t[2]]});
  int side_tag = kSideTag, base_tag = kBaseTag;
  const bool one_patch = std::all_of(surface.patches.begin(), surface.patches.end(),
                                     [&](int patch) { return patch == surface.patches.front(); });
  if (one_patch) {
    plc.tags.assign(plc.facets.size(), kTopTag);
    plc.tag_names = {{kTopTag, "top"}, {kSideTag, "sides"}, {kBaseTag, "bottom"}};
  } else {
    plc.tags = surface.patches;
    plc.tag_names = surface.patch_names;
    side_tag = *std::max_element(plc.tags.begin(), plc.tags.end()) + 1;
    base_tag = side_tag + 1;
    plc.tag_names[side_tag] = "sides";
    plc.tag_names[base_tag] = "bottom";
    sanitize_names(plc.tag_names);  // a patch of the surface already named "sides" or "bottom"
  }
  // Side walls: one vertical quad per border edge (planar: it contains the edge and `up`), on
  // base points right below the border vertices.
  std::vector<std::uint32_t> below(surface.points.size(), UINT32_MAX);
  SurfacePlc projected;  // every referenced point on the base plane, for coarse_base
  projected.points.resize(surface.points.size());
  for (std::size_t v = 0; v < surface.points.size(); ++v) {
    if (renumber[v] == UINT32_MAX) continue;
    below[v] = static_cast<std::uint32_t>(v);
    projected.points[v] = surface.points[v];
    projected.points[v][axis] = up[axis] * base_level;  // exactly on the base plane
  }
  const TriMesh base = coarse_base(surface, below, projected);
  std::vector<std::uint32_t> base_index(base.n_vertices());
  for (const auto v : base.vertices()) {
    base_index[static_cast<std::size_t>(v.idx())] = static_cast<std::uint32_t>(plc.points.size());
    plc.points.push_back(to_eigen(base.point(v)));
  }
  // The border vertices are locked: the base keeps them, and a border point of the surface is
  // found again by its position.
  std::map<std::array<double, 3>, std::uint32_t> base_at;
  for (const auto v : base.vertices())
    if (base.is_boundary(v)) {
      const Vec3 p = to_eigen(base.point(v));
      base_at[{p.x(), p.y(), p.z()}] = base_index[static_cast<std::size_t>(v.idx())];
    }
  auto below_of = [&](std::uint32_t v) { return base_at.at({projected.points[v].x(), projected.points[v].y(), projected.points[v].z()}); };
  const std::vector<std::uint32_t> loop = boundary_loop(surface);
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const std::uint32_t a = loop[i], b = loop[(i + 1) % loop.size()];
    plc.facets.push_back({renumber[b], renumber[a], below_of(a), below_of(b)});
    plc.tags.push_back(side_tag);
  }
  for (const auto f : base.faces()) {
    std::vector<std::uint32_t> corners;
    for (const auto v : base.fv_range(f)) corners.push_back(base_index[static_cast<std::size_t>(v.idx())]);
    plc.facets.push_back(corners);
    plc.tags.push_back(base_tag);
  }
  return plc;
}

}  // namespace meshprep
