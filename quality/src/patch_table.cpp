#include "meshprep/quality/patch_table.h"

#include "meshprep/core/patch_names.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace meshprep {

std::vector<PatchRow> patch_table(const TriangleSoup& surface) {
  std::map<int, PatchRow> rows;
  std::map<int, Vec3> area_normal;  // sum of the faces' normals times twice their area
  std::vector<Vec3> normals(surface.patches.size());
  for (std::size_t f = 0; f < surface.patches.size(); ++f) {
    const Triangle& t = surface.triangles[f];
    const std::vector<Vec3>& p = surface.points;
    normals[f] = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    PatchRow& row = rows[surface.patches[f]];
    ++row.faces;
    row.area += 0.5 * normals[f].norm();
    area_normal.try_emplace(surface.patches[f], Vec3::Zero()).first->second += normals[f];
  }
  // A closed patch (a whole sphere) has area vectors that sum to nothing: its mean normal is
  // rounding noise with no direction, and its normals point every way. Below sqrt(epsilon) of the
  // summed area, far above the rounding of the sum and far below any open patch, it counts as 180°.
  const double closed_fraction = std::sqrt(std::numeric_limits<double>::epsilon());
  std::map<int, double> smallest_cosine;
  for (std::size_t f = 0; f < surface.patches.size(); ++f) {
    const int tag = surface.patches[f];
    const Vec3& mean = area_normal[tag];
    double& cosine = smallest_cosine.try_emplace(tag, 1.0).first->second;
    if (mean.norm() <= closed_fraction * 2 * rows[tag].area) {
      cosine = -1;
      continue;
    }
    const double norms = normals[f].norm() * mean.norm();
    if (norms == 0) continue;
    cosine = std::min(cosine, normals[f].dot(mean) / norms);
  }
  std::vector<PatchRow> table;
  for (auto& [tag, row] : rows) {
    row.tag = tag;
    row.name = tag_name(surface.patch_names, tag, "patch");
    const double cosine = smallest_cosine.count(tag) ? smallest_cosine[tag] : 1.0;
    row.normal_spread_deg = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
    table.push_back(row);
  }
  return table;
}

nlohmann::ordered_json to_json(const std::vector<PatchRow>& table) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const PatchRow& row : table)
    rows.push_back({{"tag", row.tag},
                    {"name", row.name},
                    {"faces", row.faces},
                    {"area", row.area},
                    {"normal_spread_deg", row.normal_spread_deg}});
  return rows;
}

}  // namespace meshprep
