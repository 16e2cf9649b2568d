#include "meshprep/commands/tet_mesh_report.h"

#include "meshprep/core/patch_names.h"
#include "meshprep/fem/tet_boundary.h"
#include "meshprep/fem/tet_quality.h"
#include "meshprep/quality/topology.h"

#include <map>
#include <string>

namespace meshprep {
namespace {

using Json = nlohmann::ordered_json;

Json boundary_json(const TetMesh& mesh, const TetReadReport& read) {
  TriangleSoup boundary;
  boundary.points = mesh.points;
  boundary.triangles = tet_boundary(mesh);
  const Topology topology = analyze_topology(boundary);
  std::map<int, std::size_t> per_tag;
  for (const int tag : mesh.boundary_tags) ++per_tag[tag];
  Json tags = Json::object(), patches = Json::object();
  for (const auto& [tag, count] : per_tag) {
    tags[std::to_string(tag)] = count;
    patches[tag_name(mesh.boundary_names, tag, "boundary")] = count;
  }
  return {{"faces", boundary.triangles.size()},
          {"interface_faces", read.interface_faces},
          {"internal_faces", read.internal_faces},
          {"faces_per_tag", tags},
          {"faces_per_patch", patches},
          {"closed", topology.closed},
          {"manifold", topology.manifold},
          {"oriented", topology.oriented},
          {"components", topology.components},
          {"non_manifold_edges", topology.non_manifold_edges},
          {"non_manifold_vertices", topology.non_manifold_vertices},
          {"genus", topology.genus ? Json(*topology.genus) : Json(nullptr)}};
}

}  // namespace

Json tet_mesh_report(const TetMesh& mesh, const TetReadReport& read) {
  Json report;
  report["file"] = read.path;
  report["input"] = {{"format", read.format},
                     {"triangles_in_file", read.triangles_in_file},
                     {"duplicate_triangles", read.duplicate_triangles},
                     {"untagged_boundary_faces", read.untagged_boundary_faces},
                     {"tets_reoriented", read.tets_reoriented},
                     {"tets_inverted", read.tets_inverted},
                     {"elements_ignored", read.elements_ignored}};
  report["tet_quality"] = to_json(analyze_tet_quality(mesh));
  report["boundary"] = boundary_json(mesh, read);
  return report;
}

}  // namespace meshprep
