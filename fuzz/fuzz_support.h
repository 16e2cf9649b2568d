#pragma once
/// \file fuzz_support.h
/// What every fuzz target checks. The library may refuse an input only with its documented errors
/// (InvalidInput, IoError); any other exception escapes to libFuzzer, which reports it as a crash,
/// like a sanitizer finding, a leak or a timeout. What an input yields when it is accepted must
/// keep the library's promises: a broken invariant aborts with a message.

#include "meshprep/core/errors.h"
#include "meshprep/core/mesh.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace meshprep::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// Aborts, naming the broken invariant, unless `holds`.
inline void require(bool holds, const char* invariant) {
  if (holds) return;
  std::fprintf(stderr, "fuzz invariant broken: %s\n", invariant);
  std::abort();
}

/// The geometric targets' points: three bytes each from `at` on, coordinates 0 to 15 on a grid, x
/// and z halved when their byte's bit 16 is set (flat, folded and coincident places are common).
/// \pre the bytes hold `point_count` points from `at`
inline std::vector<Vec3> grid_points_from_bytes(const std::uint8_t* data, std::size_t at, std::size_t point_count) {
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < point_count; ++i, at += 3)
    points.push_back({(data[at] % 16) / ((data[at] & 16) ? 2.0 : 1.0), (data[at + 1] % 16) / 1.0,
                      (data[at + 2] % 16) / ((data[at + 2] & 16) ? 2.0 : 1.0)});
  return points;
}

/// The geometric targets' faces: three bytes each from `at` on (corner indices modulo
/// `point_count`), as many as the bytes hold, at most `max_faces`.
inline std::vector<Triangle> faces_from_bytes(const std::uint8_t* data, std::size_t size, std::size_t at,
                                              std::size_t point_count, std::size_t max_faces) {
  std::vector<Triangle> faces;
  for (; at + 3 <= size && faces.size() < max_faces; at += 3)
    faces.push_back({static_cast<std::uint32_t>(data[at] % point_count), static_cast<std::uint32_t>(data[at + 1] % point_count),
                     static_cast<std::uint32_t>(data[at + 2] % point_count)});
  return faces;
}

/// Runs `parse`; the library's documented errors mean a refused input, anything else escapes.
template <class Parse>
void refuse_only_with_meshprep_errors(Parse parse) {
  try {
    parse();
  } catch (const InvalidInput&) {
  } catch (const IoError&) {
  }
}

}  // namespace meshprep::fuzz
