#pragma once
// Repair step 6 (repair.h): which side of a surface crossing itself is inside.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// The generalised winding number of a surface of closed parts (Jacobson et al. 2013): the solid
/// angles its faces subtend at a point, summed and divided by 4 pi. For closed, outward parts it
/// counts how many times they wrap the point: 0 outside, 1 inside, 2 where two parts overlap. Each
/// solid angle after Van Oosterom and Strackee 1983. A closed part wraps no point outside its
/// bounding box, so only the parts whose box holds the point are summed: a surface of many parts
/// apart costs about one part a query, not all of them.
class WindingNumber {
 public:
  static constexpr std::uint32_t kNoPart = UINT32_MAX;
  /// `part_of_face[f]` names the closed part of soup.triangles[f], or is kNoPart for a face left
  /// out (an open part's). `soup` must outlive this.
  WindingNumber(const TriangleSoup& soup, const std::vector<std::uint32_t>& part_of_face);
  /// \pre q is not on the surface
  double at(const Vec3& q) const;

 private:
  struct Part {
    Vec3 lo, hi;                  // bounding box
    std::size_t begin = 0, end = 0;  // its faces in faces_
  };
  const TriangleSoup& soup_;
  std::vector<std::uint32_t> faces_;  // grouped by part
  std::vector<Part> parts_;
};

}  // namespace meshprep::detail
