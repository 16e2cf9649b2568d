#include "robust_predicates.h"

#include <tetgen.h>

#include <mutex>

// TetGen's predicates.cxx defines orient2d but tetgen.h does not declare it.
REAL orient2d(REAL* pa, REAL* pb, REAL* pc);

namespace meshprep::detail {
namespace {

std::once_flag initialised;

void initialise_once() { std::call_once(initialised, reset_robust_predicates); }

}  // namespace

void reset_robust_predicates() { exactinit(/*verbose=*/0, /*noexact=*/0, /*nofilter=*/1, 1.0, 1.0, 1.0); }

double orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  initialise_once();
  double pa[3] = {a.x(), a.y(), a.z()}, pb[3] = {b.x(), b.y(), b.z()}, pc[3] = {c.x(), c.y(), c.z()},
         pd[3] = {d.x(), d.y(), d.z()};
  return ::orient3d(pa, pb, pc, pd);
}

double orient2d(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  initialise_once();
  double pa[2] = {a.x(), a.y()}, pb[2] = {b.x(), b.y()}, pc[2] = {c.x(), c.y()};
  return ::orient2d(pa, pb, pc);
}

}  // namespace meshprep::detail
