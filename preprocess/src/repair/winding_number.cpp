#include "repair/winding_number.h"

#include <cmath>

namespace meshprep::detail {

double winding_number(const TriangleSoup& soup, const Vec3& q) {
  constexpr double kPi = 3.14159265358979323846;
  double sum = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3 a = soup.points[t[0]] - q, b = soup.points[t[1]] - q, c = soup.points[t[2]] - q;
    const double la = a.norm(), lb = b.norm(), lc = c.norm();
    // tan(omega / 2) = a . (b x c) / (|a||b||c| + (a.b)|c| + (b.c)|a| + (c.a)|b|).
    const double numerator = a.dot(b.cross(c));
    const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
    sum += 2 * std::atan2(numerator, denominator);
  }
  return sum / (4 * kPi);
}

}  // namespace meshprep::detail
