#include "repair/winding_number.h"

#include <algorithm>
#include <cmath>

namespace meshprep::detail {

WindingNumber::WindingNumber(const TriangleSoup& soup, const std::vector<std::uint32_t>& part_of_face) : soup_(soup) {
  for (std::uint32_t f = 0; f < soup.triangles.size(); ++f)
    if (part_of_face[f] != kNoPart) faces_.push_back(f);
  std::stable_sort(faces_.begin(), faces_.end(),
                   [&](std::uint32_t f, std::uint32_t g) { return part_of_face[f] < part_of_face[g]; });
  for (std::size_t i = 0; i < faces_.size();) {
    Part part{Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY), i, i};
    for (; part.end < faces_.size() && part_of_face[faces_[part.end]] == part_of_face[faces_[i]]; ++part.end)
      for (const std::uint32_t v : soup.triangles[faces_[part.end]]) {
        part.lo = part.lo.cwiseMin(soup.points[v]);
        part.hi = part.hi.cwiseMax(soup.points[v]);
      }
    i = part.end;
    parts_.push_back(part);
  }
}

double WindingNumber::at(const Vec3& q) const {
  constexpr double kPi = 3.14159265358979323846;
  double sum = 0;
  for (const Part& part : parts_) {
    if ((q.array() < part.lo.array()).any() || (q.array() > part.hi.array()).any()) continue;
    for (std::size_t i = part.begin; i < part.end; ++i) {
      const Triangle& t = soup_.triangles[faces_[i]];
      const Vec3 a = soup_.points[t[0]] - q, b = soup_.points[t[1]] - q, c = soup_.points[t[2]] - q;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      // tan(omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|).
      const double numerator = a.dot(b.cross(c));
      const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
      sum += 2 * std::atan2(numerator, denominator);
    }
  }
  return sum / (4 * kPi);
}

}  // namespace meshprep::detail
