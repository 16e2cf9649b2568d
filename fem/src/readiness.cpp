#include "meshprep/fem/readiness.h"

#include "meshprep/quality/coincident_vertices.h"
#include "meshprep/quality/self_intersections.h"
#include "meshprep/quality/topology.h"
#include "meshprep/quality/triangle_metrics.h"

#include <algorithm>
#include <set>
#include <sstream>

namespace meshprep {
namespace {

constexpr std::size_t kListed = 100;

std::string count_of(std::size_t n, const char* singular, const char* plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

void add(Readiness& r, const char* check, std::size_t count, std::string what, std::string hint,
         std::vector<std::size_t> faces) {
  if (count == 0) return;
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  if (faces.size() > kListed) faces.resize(kListed);
  r.problems.push_back({check, count, std::move(what), std::move(hint), std::move(faces)});
}

std::vector<std::size_t> concat(std::vector<std::size_t> a, const std::vector<std::size_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

}  // namespace

Readiness check_fem_readiness(const TriangleSoup& input, bool known_free_of_self_intersections) {
  Readiness r;
  // Split vertices first: they open every edge along them and make touching faces count as
  // intersecting, so the other checks look at the welded surface and describe its shape.
  const CoincidentVertices welding = find_coincident_vertices(input);
  const TriangleSoup& surface = welding.merged > 0 ? welding.welded : input;
  add(r, "welded", welding.merged,
      count_of(welding.merged, "vertex lies", "vertices lie") +
          " exactly on another vertex: the faces around them are not connected (the file splits its vertices, "
          "as VTK's normals filter writes them)",
      "weld them (meshprep repair); the other checks describe the welded surface",
      welding.faces);
  const Topology topo = analyze_topology(surface);
  add(r, "closed", topo.border_edges,
      count_of(topo.border_edges, "border edge", "border edges") + " in " +
          count_of(topo.boundary_loops, "boundary loop", "boundary loops") + ": the surface is not closed",
      "fill the holes (e.g. MeshLab's Close Holes); a terrain height field can be closed into a block with "
      "--extrude-base DEPTH",
      topo.border_edge_faces);
  add(r, "manifold", topo.non_manifold_edges + topo.non_manifold_vertices + topo.repeated_index_faces,
      count_of(topo.non_manifold_edges, "edge", "edges") + " shared by more than two faces, " +
          count_of(topo.non_manifold_vertices, "vertex", "vertices") + " joining separate fans, " +
          count_of(topo.repeated_index_faces, "face", "faces") + " naming a vertex twice",
      "remove the extra faces on each listed edge and split or remove faces at pinched vertices",
      concat(concat(topo.non_manifold_edge_faces, topo.non_manifold_vertex_faces), topo.repeated_index_face_indices));
  if (topo.manifold)
    add(r, "oriented", topo.inconsistent_edges,
        count_of(topo.inconsistent_edges, "edge is", "edges are") + " traversed the same way by both faces",
        "flip the listed faces so that neighbouring faces agree (MeshLab: Re-Orient all faces coherently)",
        topo.inconsistent_edge_faces);
  std::vector<std::size_t> degenerate;
  std::size_t n_degenerate = 0;
  const std::vector<TriangleShape> shapes = triangle_shapes(surface);
  for (std::size_t f = 0; f < shapes.size(); ++f)
    if (shapes[f].degenerate && !(surface.triangles[f][0] == surface.triangles[f][1] ||
                                  surface.triangles[f][1] == surface.triangles[f][2] ||
                                  surface.triangles[f][0] == surface.triangles[f][2])) {
      ++n_degenerate;
      if (degenerate.size() < kListed) degenerate.push_back(f);
    }
  add(r, "degenerate_faces", n_degenerate, count_of(n_degenerate, "face has", "faces have") + " zero area",
      "collapse the listed faces' shortest edges (zero-area faces have no normal for TetGen)", degenerate);
  add(r, "duplicate_faces", topo.duplicate_faces,
      count_of(topo.duplicate_faces, "face repeats", "faces repeat") + " another face's vertices",
      "delete the listed duplicate faces", topo.duplicate_face_indices);
  const SelfIntersections si = known_free_of_self_intersections && welding.merged == 0
                                   ? SelfIntersections{}
                                   : find_self_intersections(surface, 100000);
  std::vector<std::size_t> si_faces;
  std::ostringstream first_pairs;
  for (std::size_t i = 0; i < si.pairs.size() && si_faces.size() < kListed; ++i) {
    si_faces.push_back(si.pairs[i].first);
    si_faces.push_back(si.pairs[i].second);
    if (i < 3) first_pairs << (i ? ", " : " (first: ") << si.pairs[i].first << '/' << si.pairs[i].second;
  }
  if (!si.pairs.empty()) first_pairs << ')';
  add(r, "self_intersections", si.count,
      count_of(si.count, "pair", "pairs") + (si.capped ? " or more" : "") + " of faces intersect" + first_pairs.str(),
      "the surface passes through itself; fix the listed faces (open the --diagnose mesh next to the input)",
      si_faces);
  if (topo.closed && topo.oriented) r.inward_oriented = signed_volume(surface) < 0;
  r.isolated_vertices = topo.isolated_vertices - welding.merged;  // merged away: not isolated in the input
  return r;
}

TriangleSoup diagnosis_mesh(const TriangleSoup& surface, const Readiness& readiness) {
  std::set<std::size_t> faces;
  for (const ReadinessProblem& p : readiness.problems) faces.insert(p.faces.begin(), p.faces.end());
  TriangleSoup out;
  std::vector<std::uint32_t> renumber(surface.points.size(), UINT32_MAX);
  for (std::size_t f : faces) {
    Triangle t = surface.triangles[f];
    for (auto& v : t) {
      if (renumber[v] == UINT32_MAX) {
        renumber[v] = static_cast<std::uint32_t>(out.points.size());
        out.points.push_back(surface.points[v]);
      }
      v = renumber[v];
    }
    out.triangles.push_back(t);
  }
  return out;
}

nlohmann::ordered_json to_json(const Readiness& readiness) {
  nlohmann::ordered_json j;
  j["ready"] = readiness.ready();
  j["isolated_vertices"] = readiness.isolated_vertices;
  j["problems"] = nlohmann::ordered_json::array();
  for (const ReadinessProblem& p : readiness.problems)
    j["problems"].push_back(
        {{"check", p.check}, {"count", p.count}, {"what", p.what}, {"hint", p.hint}, {"faces", p.faces}});
  return j;
}

}  // namespace meshprep
