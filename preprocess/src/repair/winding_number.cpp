#include "repair/winding_number.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace meshprep::detail {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A leaf holds at most this many faces: summed exactly when near.
constexpr std::uint32_t kLeafFaces = 8;

std::vector<std::uint32_t> every_face(const TriangleSoup& soup) {
  std::vector<std::uint32_t> faces(soup.triangles.size());
  std::iota(faces.begin(), faces.end(), 0u);
  return faces;
}

}  // namespace

double winding_share(const std::vector<Vec3>& points, const Triangle& t, const Vec3& q) {
  const Vec3 a = points[t[0]] - q, b = points[t[1]] - q, c = points[t[2]] - q;
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  // tan(omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|).
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2 * std::atan2(numerator, denominator) / (4 * kPi);
}

WindingNumber::WindingNumber(const TriangleSoup& soup) : WindingNumber(soup, every_face(soup)) {}

WindingNumber::WindingNumber(const TriangleSoup& soup, std::vector<std::uint32_t> faces)
    : soup_(soup), faces_(std::move(faces)) {
  std::vector<Vec3> centres(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    centres[f] = (soup.points[t[0]] + soup.points[t[1]] + soup.points[t[2]]) / 3;
  }
  nodes_.reserve(4 * faces_.size() / kLeafFaces + 2);
  if (faces_.empty()) return;
  nodes_.emplace_back();
  build(0, 0, static_cast<std::uint32_t>(faces_.size()), centres);
}

// The node's moments are its faces' sums; it splits at the median of the longest side of the
// faces' centres until kLeafFaces.
void WindingNumber::build(std::uint32_t index, std::uint32_t begin, std::uint32_t end, const std::vector<Vec3>& centres) {
  Node node;
  node.begin = begin;
  node.end = end;
  double area = 0;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY), mean = Vec3::Zero();
  for (std::uint32_t i = begin; i < end; ++i) {
    const Triangle& t = soup_.triangles[faces_[i]];
    const Vec3 vector = 0.5 * (soup_.points[t[1]] - soup_.points[t[0]]).cross(soup_.points[t[2]] - soup_.points[t[0]]);
    const double a = vector.norm();
    node.area_vector += vector;
    node.centroid += a * centres[faces_[i]];
    mean += centres[faces_[i]];
    area += a;
    lo = lo.cwiseMin(centres[faces_[i]]);
    hi = hi.cwiseMax(centres[faces_[i]]);
  }
  // Faces of no area (a soup may hold them) weigh nothing; a node of only those sits at their mean.
  node.centroid = area > 0 ? Vec3(node.centroid / area) : Vec3(mean / static_cast<double>(end - begin));
  for (std::uint32_t i = begin; i < end; ++i) {
    const Triangle& t = soup_.triangles[faces_[i]];
    for (const std::uint32_t v : t) node.radius = std::max(node.radius, (soup_.points[v] - node.centroid).norm());
    const Vec3 vector = 0.5 * (soup_.points[t[1]] - soup_.points[t[0]]).cross(soup_.points[t[2]] - soup_.points[t[0]]);
    node.moment += vector * (centres[faces_[i]] - node.centroid).transpose();
  }
  if (end - begin <= kLeafFaces) {
    nodes_[index] = node;
    return;
  }
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  const std::uint32_t middle = begin + (end - begin) / 2;
  std::nth_element(faces_.begin() + begin, faces_.begin() + middle, faces_.begin() + end,
                   [&](std::uint32_t f, std::uint32_t g) {
                     return centres[f][axis] != centres[g][axis] ? centres[f][axis] < centres[g][axis] : f < g;
                   });
  node.first_child = static_cast<std::uint32_t>(nodes_.size());  // two slots: one index names both
  nodes_.emplace_back();
  nodes_.emplace_back();
  nodes_[index] = node;
  build(node.first_child, begin, middle, centres);
  build(node.first_child + 1, middle, end, centres);
}

double WindingNumber::at(const Vec3& q) const {
  if (nodes_.empty()) return 0;
  double sum = 0;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const Node& node = nodes_[stack.back()];
    stack.pop_back();
    const Vec3 to_centroid = node.centroid - q;
    const double distance = to_centroid.norm();
    if (distance > kFarFactor * node.radius) {
      // A face of area vector A at x subtends A . grad G(x - q), G(r) = -1 / (4 pi |r|): about the
      // centroid c, A . grad G(c - q) + A . H(c - q) (x - c), H = (I / |r|^3 - 3 r r^T / |r|^5) / (4 pi).
      const double d3 = distance * distance * distance;
      const Eigen::Matrix3d hessian =
          (Eigen::Matrix3d::Identity() / d3 - 3 * to_centroid * to_centroid.transpose() / (d3 * distance * distance)) /
          (4 * kPi);
      sum += node.area_vector.dot(to_centroid) / (4 * kPi * d3) + (hessian.cwiseProduct(node.moment)).sum();
    } else if (node.first_child == 0) {
      for (std::uint32_t i = node.begin; i < node.end; ++i) sum += winding_share(soup_.points, soup_.triangles[faces_[i]], q);
    } else {
      stack.push_back(node.first_child);
      stack.push_back(node.first_child + 1);
    }
  }
  return sum;
}

}  // namespace meshprep::detail
