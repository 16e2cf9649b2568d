#include "repair/fill_holes.h"

#include "repair/fair_patch.h"
#include "repair/refine_patch.h"
#include "repair/sheet_outlines.h"
#include "repair/triangulate_hole.h"
#include "shared/triangle_angles.h"

#include "meshprep/quality/face_edges.h"
#include "meshprep/quality/surface_distance.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace meshprep::detail {
namespace {

// The dynamic programme costs n^3 / 6 face weights. Measured here (a wavy circle, Release): 500
// rim vertices take 0.26 s with the dihedral weight and 0.15 s with the area alone, 1000 take
// 2.1 s and 1.25 s, 2000 take 12.7 s with the area alone; and a grid's 2000- and 1800-vertex rims
// took 98 s to fill in all (760k faces refined and faired). So: the dihedral weight up
// to 500, the area alone (Liepa's minimum-area variant, 1.7 x cheaper) up to 1000, and longer
// rims are left open rather than stall the run.
constexpr std::size_t kDihedralRim = 500;
constexpr std::size_t kLongestRim = 1000;

struct Border {
  std::uint32_t to, face;
};

// Whether face f has the three rim vertices (copies of a split point taken as their lowest).
bool is_face(const TriangleSoup& soup, std::uint32_t f, const std::vector<std::uint32_t>& rim,
             const std::vector<std::uint32_t>& lowest) {
  Triangle t = soup.triangles[f];
  for (std::uint32_t& v : t) v = lowest[v];
  return std::is_permutation(t.begin(), t.end(), rim.begin());
}

// The largest distance of `vertices` to the least-squares plane of the rim's vertices (through
// their centroid, normal along the covariance's smallest eigenvector).
double plane_distance(const std::vector<Vec3>& points, const std::vector<std::uint32_t>& rim,
                      const std::vector<Triangle>& patch) {
  Vec3 centroid = Vec3::Zero();
  for (const std::uint32_t v : rim) centroid += points[v];
  centroid /= static_cast<double>(rim.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const std::uint32_t v : rim) covariance += (points[v] - centroid) * (points[v] - centroid).transpose();
  const Vec3 normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
  double distance = 0;
  for (const Triangle& t : patch)
    for (const std::uint32_t v : t) distance = std::max(distance, std::abs(normal.dot(points[v] - centroid)));
  return distance;
}

// "0.97".
std::string two_digits(double value) {
  char text[16];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

}  // namespace

std::vector<RepairHole> fill_holes(TriangleSoup& soup, const std::vector<FaceEdge>& uses,
                                   std::optional<double> max_hole) {
  std::unordered_map<std::uint32_t, Border> border;  // by its first vertex, as its face runs it
  std::vector<std::uint32_t> starts;
  for (std::size_t i = 0; i < uses.size(); ++i) {
    const FaceEdge& e = uses[i];
    if ((i > 0 && uses[i - 1].key == e.key) || (i + 1 < uses.size() && uses[i + 1].key == e.key)) continue;
    const std::uint32_t from = e.forward ? e.lo() : e.hi(), to = e.forward ? e.hi() : e.lo();
    if (border.emplace(from, Border{to, e.face}).second) starts.push_back(from);
  }
  if (border.empty()) return {};  // closed: the common case costs one walk over the edges
  // Copies of one point on the border are split_nonmanifold's, of a bow-tie on a rim: each answers
  // to the lowest, and a loop that reaches one copy leaves from another's border edge, across the
  // empty sector between their fans, so that the patches fill the sectors and the copies make one
  // fan again (repair.cpp welds them back). With two fans the other copy is the neighbour across
  // the sector; with more, the first free one is taken, which may not be (then it stays split).
  std::vector<std::uint32_t> lowest(soup.points.size());
  std::iota(lowest.begin(), lowest.end(), std::uint32_t{0});
  std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> copies;
  std::vector<std::uint32_t> by_point(starts);
  std::sort(by_point.begin(), by_point.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Vec3 &p = soup.points[a], &q = soup.points[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  });
  for (std::size_t i = 1; i < by_point.size(); ++i)
    if (soup.points[by_point[i]] == soup.points[by_point[i - 1]]) {
      lowest[by_point[i]] = lowest[by_point[i - 1]];
      auto& same = copies[lowest[by_point[i]]];
      if (same.empty()) same.push_back(by_point[i - 1]);
      same.push_back(by_point[i]);
    }
  std::unordered_set<std::uint64_t> edges;
  std::vector<std::vector<std::uint32_t>> neighbours(soup.points.size());
  for (std::size_t i = 0; i < uses.size(); ++i) {
    if (i > 0 && uses[i - 1].key == uses[i].key) continue;
    const std::uint32_t a = lowest[uses[i].lo()], b = lowest[uses[i].hi()];
    edges.insert(edge_key(a, b));
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  std::unordered_set<std::uint32_t> walked;
  // Where the walk goes on from `v`: another copy of v's point whose gap is not walked yet, else v.
  const auto leave = [&](std::uint32_t v) {
    const auto found = copies.find(lowest[v]);
    if (found != copies.end())
      for (const std::uint32_t copy : found->second)
        if (copy != v && !walked.count(copy)) return copy;
    return v;
  };
  // Every loop is walked before any is filled: the default rule weighs each against the others.
  struct Loop {
    HoleRim rim;
    RepairHole hole;
    LoopBorder border;
    std::unordered_map<int, double> rim_length_by_patch;  // when the soup has patches
  };
  std::vector<Loop> loops;
  for (const std::uint32_t start : starts) {
    if (walked.count(start)) continue;
    Loop loop;
    loop.border.face = border.at(start).face;
    const Vec3 origin = soup.points[start];
    std::uint32_t v = start;
    do {
      walked.insert(v);
      const Border& b = border.at(v);
      loop.rim.vertices.push_back(lowest[v]);
      loop.rim.face_normals.push_back(unit_normal(soup, b.face));
      loop.hole.rim_length += (soup.points[b.to] - soup.points[v]).norm();
      if (!soup.patches.empty()) loop.rim_length_by_patch[soup.patches[b.face]] += (soup.points[b.to] - soup.points[v]).norm();
      loop.border.vector_area += (soup.points[v] - origin).cross(soup.points[b.to] - origin) / 2;
      v = leave(b.to);
    } while (border.count(v) && !walked.count(v));
    loop.hole.rim_vertices = loop.rim.vertices.size();
    loop.border.closes = lowest[v] == lowest[start];
    loops.push_back(std::move(loop));
  }
  std::vector<LoopSheet> sheets;
  if (!max_hole) {
    std::vector<LoopBorder> borders;
    for (const Loop& loop : loops) borders.push_back(loop.border);
    sheets = sheet_outlines(soup, borders);
  }
  const double max_rim_length = max_hole ? *max_hole * bbox_diagonal(soup) : 0;
  std::vector<RepairHole> holes;
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const HoleRim& rim = loops[l].rim;
    RepairHole& hole = loops[l].hole;
    if (!loops[l].border.closes)
      hole.left_open = "its border does not close into a loop (a non-manifold or inconsistently oriented border)";
    else if (max_hole && hole.rim_length > max_rim_length)
      hole.left_open = "its rim is longer than max_hole";
    else if (!max_hole && sheets[l].outline && sheets[l].one_sidedness > kSheetOneSidedness)
      hole.left_open = "it is the outline of an open sheet (one-sidedness " + two_digits(sheets[l].one_sidedness) +
                       " > " + two_digits(kSheetOneSidedness) +
                       ": a terrain, a mask or a bowl, not a solid's missing part; given a max_hole, loops are filled by length)";
    else if (rim.vertices.size() > kLongestRim)
      hole.left_open = "its rim has more than " + std::to_string(kLongestRim) + " vertices";
    else if (rim.vertices.size() == 3 && is_face(soup, loops[l].border.face, rim.vertices, lowest))
      hole.left_open = "its rim is a lone face's border (a patch would repeat the face)";
    if (!hole.left_open.empty()) {
      holes.push_back(std::move(hole));
      continue;
    }
    std::vector<Triangle> patch = triangulate_hole(soup.points, rim, edges, rim.vertices.size() <= kDihedralRim);
    if (patch.empty()) {
      hole.left_open = "no triangulation avoids the surface's edges";
      holes.push_back(std::move(hole));
      continue;
    }
    // Liepa's density: each rim vertex's mean edge length on the surface.
    std::unordered_map<std::uint32_t, double> scale;
    for (const std::uint32_t r : rim.vertices) {
      double sum = 0;
      for (const std::uint32_t w : neighbours[r]) sum += (soup.points[w] - soup.points[r]).norm();
      scale[r] = sum / static_cast<double>(neighbours[r].size());
    }
    const auto first_new = static_cast<std::uint32_t>(soup.points.size());
    refine_patch(soup.points, scale, patch, edges);
    hole.faired = fair_patch(soup.points, patch, first_new, neighbours);
    hole.filled = true;
    hole.patch_faces = patch.size();
    hole.patch_vertices = soup.points.size() - first_new;
    for (const Triangle& t : patch)
      hole.patch_area +=
          (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]).norm() / 2;
    hole.plane_distance = plane_distance(soup.points, rim.vertices, patch);
    soup.triangles.insert(soup.triangles.end(), patch.begin(), patch.end());
    if (!soup.patches.empty()) {  // the patch joins the boundary patch with the most of its rim
      const auto& by_patch = loops[l].rim_length_by_patch;
      const auto most = std::max_element(by_patch.begin(), by_patch.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second < b.second : a.first > b.first;
      });
      soup.patches.resize(soup.triangles.size(), most->first);
    }
    // The next holes see the patch as surface: two of them may share a split point.
    for (const Triangle& t : patch)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = t[k], b = t[(k + 1) % 3];
        if (!edges.insert(edge_key(a, b)).second) continue;
        if (a < neighbours.size()) neighbours[a].push_back(b);
        if (b < neighbours.size()) neighbours[b].push_back(a);
      }
    holes.push_back(std::move(hole));
  }
  return holes;
}

}  // namespace meshprep::detail
