#include "readers.h"

#include "meshprep/core/errors.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace meshprep::detail {
namespace {

// The stages multiply up to six lengths: the normal equations of a local least-squares cubic square
// its cubic terms, TetGen's insphere test multiplies a squared length by a 3 x 3 determinant of
// lengths, volumes and squared areas are products of three and four. A product of six extents
// overflows a double beyond the sixth root of its largest value, about 2.4e51, whatever the
// unit; inputs that span more could hang a stage or make its figures infinite (issue 30, item 4).
double largest_extent() { return std::cbrt(std::sqrt(std::numeric_limits<double>::max())); }

// At the other end, the angle between two faces' normals multiplies eight lengths (each normal a
// cross product of two edges, then their cross product): below the eighth root of the smallest
// normal double, about 3.5e-39, every dihedral angle comes out 0 or 180 degrees (issue 45, item
// 14, saw it from about 1e-38), and below the cube root (2.8e-103) every volume is 0. A part's
// edges are shorter than its extent, so the bound leaves them a factor of a million: a span under
// 3.5e-33 is refused.
double smallest_extent() { return std::pow(std::numeric_limits<double>::min(), 1.0 / 8) * 1e6; }

std::string shown(double value) {
  std::ostringstream out;
  out << std::setprecision(3) << value;
  return out.str();
}

}  // namespace

void fail(const std::string& path, const std::string& problem) { throw InvalidInput(path + ": " + problem); }

void refuse_folder(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) fail(path, "a folder, not a mesh file: give one of its files");
}

std::string unknown_extension_problem(const std::string& extension) {
  const std::string supported = " (supported: .off, .obj, .ply, .stl)";
  if (extension.empty()) return "no file extension to choose the format from" + supported;
  return "unknown mesh extension '." + extension + "'" + supported;
}

std::string at_line(std::size_t line) { return "line " + std::to_string(line) + ": "; }

bool is_finite(const Vec3& p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

std::string non_finite_text(const Vec3& p) {
  for (int i = 0; i < 3; ++i) {
    if (std::isnan(p[i])) return "nan";
    if (std::isinf(p[i])) return p[i] > 0 ? "inf" : "-inf";
  }
  return "finite";
}

void check_extent(const std::string& path, const std::vector<Vec3>& points) {
  if (points.empty()) return;
  Vec3 low = points.front(), high = points.front();
  for (const Vec3& p : points) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  for (int axis = 0; axis < 3; ++axis) {
    const double extent = high[axis] - low[axis];  // inf when the difference overflows
    if (!(extent <= largest_extent()))
      fail(path, "the coordinates span " + shown(extent) + " along " + "xyz"[axis] + ", more than " +
                     shown(largest_extent()) + " (where a product of six lengths overflows a double)");
  }
  // All points at one place are left to the checks that name what that makes of the faces.
  const double extent = (high - low).maxCoeff();
  if (extent > 0 && extent < smallest_extent())
    fail(path, "the coordinates span only " + shown(extent) + ", less than " + shown(smallest_extent()) +
                   " (where products of the lengths underflow a double and every angle is lost); scale the part up "
                   "(is it in the wrong unit?)");
}

std::size_t capped_count(std::uint64_t announced, std::size_t bytes, std::size_t min_bytes_each) {
  return static_cast<std::size_t>(std::min<std::uint64_t>(announced, bytes / std::max<std::size_t>(min_bytes_each, 1)));
}

void add_polygon(TriangleSoup& soup, const std::vector<std::uint32_t>& corners, ReadReport& report, int patch) {
  ++report.faces_in_file;
  if (corners.size() > 3) ++report.polygons_triangulated;
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    soup.triangles.push_back({corners[0], corners[i], corners[i + 1]});
  }
  if (patch != 0 || !soup.patches.empty()) {
    soup.patches.resize(soup.triangles.size() - (corners.size() - 2), 0);
    soup.patches.resize(soup.triangles.size(), patch);
  }
}

int GroupTags::tag(TriangleSoup& soup, const std::string& name) {
  const auto [it, added] = tag_of_.try_emplace(name, static_cast<int>(tag_of_.size()) + 1);
  if (added) soup.patch_names[it->second] = name;
  return it->second;
}

}  // namespace meshprep::detail
