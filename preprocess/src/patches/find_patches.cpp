// Boundary patches found from the creases, or kept from the file, then edited (patches.h).
#include "meshprep/preprocess/patches/patches.h"

#include "shared/creases.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/union_find.h"
#include "meshprep/preprocess/patches/patches_parameters.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace meshprep {
namespace {

// The patches bounded by the creases, tagged 1, 2, ... by decreasing area (ties: by first face).
void segment(TriangleSoup& surface, double feature_angle_deg) {
  MeshBuildReport build;
  const TriMesh mesh = mesh_from_soup(surface, &build);
  if (!build.dropped_faces.empty())
    throw InvalidInput(dropped_faces_problem(surface, build) +
                       "; finding patches needs a manifold surface (meshprep repair mends it)");
  const std::vector<char> crease =
      detail::creases(mesh, std::cos(feature_angle_deg * M_PI / 180.0), /*between_planes=*/true);
  detail::UnionFind regions(static_cast<std::uint32_t>(mesh.n_faces()));
  for (const auto e : mesh.edges()) {
    if (mesh.is_boundary(e) || crease[static_cast<std::size_t>(e.idx())]) continue;
    regions.unite(static_cast<std::uint32_t>(mesh.face_handle(mesh.halfedge_handle(e, 0)).idx()),
                  static_cast<std::uint32_t>(mesh.face_handle(mesh.halfedge_handle(e, 1)).idx()));
  }
  std::map<std::uint32_t, double> area;  // by region root
  std::map<std::uint32_t, std::size_t> first_face;
  for (std::size_t f = 0; f < surface.triangles.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    const std::vector<Vec3>& p = surface.points;
    const std::uint32_t root = regions.find(static_cast<std::uint32_t>(f));
    area[root] += 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
    first_face.try_emplace(root, f);
  }
  // Areas compared to 9 digits of the whole: equal sides of a box, rounded differently once the
  // part is turned or scaled, keep their order (the first face's) and so their names.
  double total = 0;
  for (const auto& [root, a] : area) total += a;
  std::map<std::uint32_t, long long> rank_area;
  for (const auto& [root, a] : area) rank_area[root] = total > 0 ? std::llround(a / total * 1e9) : 0;
  std::vector<std::uint32_t> roots;
  for (const auto& [root, a] : area) roots.push_back(root);
  std::sort(roots.begin(), roots.end(), [&](std::uint32_t a, std::uint32_t b) {
    return rank_area[a] != rank_area[b] ? rank_area[a] > rank_area[b] : first_face[a] < first_face[b];
  });
  std::map<std::uint32_t, int> tag_of;
  surface.patch_names.clear();
  for (std::size_t k = 0; k < roots.size(); ++k) {
    const int tag = static_cast<int>(k) + 1;
    tag_of[roots[k]] = tag;
    surface.patch_names[tag] = "patch_" + std::to_string(tag);
  }
  surface.patches.resize(surface.triangles.size());
  for (std::size_t f = 0; f < surface.triangles.size(); ++f)
    surface.patches[f] = tag_of[regions.find(static_cast<std::uint32_t>(f))];
}

std::string known_names(const TagNames& names) {
  std::string list;
  for (const auto& [tag, name] : names) list += (list.empty() ? "" : ", ") + name;
  return list.empty() ? "none" : list;
}

int tag_named(const TagNames& names, const std::string& name, const char* edit) {
  for (const auto& [tag, known] : names)
    if (known == name) return tag;
  throw InvalidInput(std::string(edit) + ": no patch is named '" + name + "' (the patches: " + known_names(names) + ")");
}

// Applies the merges then the renames to `names`; `retag(from, to)` moves the faces of a merged
// patch. Returns what changed.
template <class Retag>
PatchResult edit(TagNames& names, const PatchParams& params, const Retag& retag) {
  PatchResult result;
  for (const std::vector<std::string>& merge : params.merges) {
    if (merge.size() < 2)
      throw InvalidInput("--merge: name at least two patches, the first keeping the faces of the others");
    const int into = tag_named(names, merge.front(), "--merge");
    for (std::size_t i = 1; i < merge.size(); ++i) {
      const int from = tag_named(names, merge[i], "--merge");
      if (from == into) continue;
      retag(from, into);
      names.erase(from);
      ++result.merged;
    }
  }
  for (const auto& [from, to] : params.renames) {
    const int tag = tag_named(names, from, "--rename");
    const std::string clean = sanitized_name(to);
    for (const auto& [other, name] : names)
      if (other != tag && name == clean)
        throw InvalidInput("--rename " + from + "=" + to + ": a patch is named '" + clean + "' already (--merge " +
                           from + "," + clean + " joins them)");
    names[tag] = clean;
    result.renamed.push_back({tag, from, clean});
  }
  const std::vector<RenamedTag> made_valid = sanitize_names(names);
  result.renamed.insert(result.renamed.end(), made_valid.begin(), made_valid.end());
  result.patches = names.size();
  return result;
}

}  // namespace

void check_patch_edits(const TagNames& names, const PatchParams& params) {
  TagNames copy = names;
  edit(copy, params, [](int, int) {});
}

PatchResult find_patches(TriangleSoup& surface, const PatchParams& params) {
  const double angle = params.feature_angle_deg.value_or(kDefaultCreaseAngleDeg);
  check_parameter("patches", patch_parameters().feature_angle_deg, angle);
  const bool segmenting = surface.patches.empty() || params.resegment;
  if (segmenting) segment(surface, angle);
  PatchResult result = edit(surface.patch_names, params, [&](int from, int into) {
    std::replace(surface.patches.begin(), surface.patches.end(), from, into);
  });
  result.segmented = segmenting;
  result.feature_angle_deg = angle;
  return result;
}

nlohmann::ordered_json to_json(const PatchResult& result) {
  nlohmann::ordered_json renamed = nlohmann::ordered_json::array();
  for (const RenamedTag& r : result.renamed) renamed.push_back({{"tag", r.tag}, {"from", r.from}, {"to", r.to}});
  return {{"segmented", result.segmented},
          {"feature_angle_deg", result.feature_angle_deg},
          {"patches", result.patches},
          {"merged", result.merged},
          {"renamed", renamed}};
}

}  // namespace meshprep
