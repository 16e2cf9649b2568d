#include "exact_orientation.h"

#include <tetgen.h>

#include <mutex>

namespace meshprep::improve {
namespace {

std::once_flag initialised;

// Shewchuk's error bounds; without the static filter (nofilter = 1) every sign that the
// floating-point determinant cannot decide goes to the adaptive exact stages.
void initialise() { exactinit(/*verbose=*/0, /*noexact=*/0, /*nofilter=*/1, 1.0, 1.0, 1.0); }

}  // namespace

bool positively_oriented(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  std::call_once(initialised, initialise);
  double pa[3] = {a.x(), a.y(), a.z()}, pb[3] = {b.x(), b.y(), b.z()}, pc[3] = {c.x(), c.y(), c.z()},
         pd[3] = {d.x(), d.y(), d.z()};
  // Shewchuk's orient3d is positive when d lies below the plane of a, b, c seen counter-clockwise
  // from above: the opposite sign of our volume.
  return ::orient3d(pa, pb, pc, pd) < 0;
}

}  // namespace meshprep::improve
