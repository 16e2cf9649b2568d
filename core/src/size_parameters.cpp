#include "meshprep/core/size_parameters.h"

#include "meshprep/core/errors.h"
#include "meshprep/core/patch_names.h"

#include <cmath>
#include <limits>

namespace meshprep {

const SizeParameters& size_parameters() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  static const std::string length = "a length, or a percentage of the bounding-box diagonal such as 2%";
  static const SizeParameters parameters{
      {"size", "--size",
       "the element size (target edge length) wherever nothing asks for less: " + length +
           "; unset: the input's own density. Surface and tets follow it",
       {0, inf, true, true}},
      {"size_min", "--size-min", "no element size under this (curvature and thickness included): " + length, {0, inf, true, true}},
      {"size_max", "--size-max", "no element size over this: " + length, {0, inf, true, true}},
      {"grading", "--grading",
       "neighbouring elements' sizes differ by at most this ratio: the size grows by at most (grading - 1) per unit "
       "of distance from where it is asked for; auto: 1.3 once a size is set, else the enhancement's own 1.5",
       {1, 100}},
      {"curvature_points", "--curvature-points",
       "elements per full turn on a curved surface (a circle of radius r gets edges of 2 pi r / N); unset: only the "
       "fidelity bound's chord limits them",
       {0, 10000, true, false}},
      {"thickness_layers", "--thickness-layers", "elements across a thin wall at least (its thickness over this); unset: 1",
       {0, 1000, true, false}},
      {"patches", "--size",
       "the element size on the faces of a named boundary patch (a length or a percentage): finer than the size "
       "around it, graded from it by the grading",
       {}},
      {"regions", "",
       "boxes and balls of space with an element size of their own, finer than the size around them, graded from "
       "them by the grading",
       {}}};
  return parameters;
}

void check_size_params(const SizeParams& params) {
  const SizeParameters& info = size_parameters();
  for (const auto& [field, value] : {std::pair{&info.size, params.size}, {&info.size_min, params.size_min}, {&info.size_max, params.size_max}})
    if (value) check_parameter("size", *field, value->value);
  if (params.grading) check_parameter("size", info.grading, *params.grading);
  if (params.curvature_points) check_parameter("size", info.curvature_points, *params.curvature_points);
  if (params.thickness_layers) check_parameter("size", info.thickness_layers, *params.thickness_layers);
  for (const auto& [name, size] : params.patch_sizes) {
    if (!is_valid_name(name)) throw InvalidInput("size: '" + name + "' is no patch name: " + kNameRule);
    check_parameter("size", info.size, size.value);
  }
  for (const SizeRegion& region : params.regions) {
    check_parameter("size", info.size, region.size.value);
    const bool finite = region.lo.allFinite() && region.hi.allFinite() && region.center.allFinite() && std::isfinite(region.radius);
    if (!finite) throw InvalidInput("size: a region's coordinates must be finite");
    if (region.shape == SizeRegion::Shape::box && (region.lo.array() > region.hi.array()).any())
      throw InvalidInput("size: a box region's lower corner must be below its upper corner in x, y and z");
    if (region.shape == SizeRegion::Shape::sphere && !(region.radius > 0))
      throw InvalidInput("size: a sphere region's radius must be positive, not " + parameter_text(region.radius));
  }
  if (params.size_min && params.size_max && params.size_min->relative == params.size_max->relative &&
      params.size_min->value > params.size_max->value)
    throw InvalidInput("size: size_min (" + length_text(*params.size_min) + ") is over size_max (" +
                       length_text(*params.size_max) + ")");
}

}  // namespace meshprep
