#pragma once
/// \file face_edges.h
/// Every face's three edges, sorted so that the uses of one undirected edge are adjacent: the
/// walk behind topology (border, non-manifold and inconsistent edges), the seams of split vertices
/// and the repair's orientation.

#include "meshprep/core/soup_view.h"

#include <cstdint>
#include <vector>

namespace meshprep {

/// The undirected edge a-b as one number: smaller index << 32 | larger.
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? std::uint64_t{a} << 32 | b : std::uint64_t{b} << 32 | a;
}

/// One directed edge of a face, keyed by its undirected vertex pair.
struct FaceEdge {
  std::uint64_t key;  ///< edge_key of its two vertices
  std::uint32_t face;
  bool forward;  ///< traversed from the smaller to the larger vertex index

  std::uint32_t lo() const { return static_cast<std::uint32_t>(key >> 32); }
  std::uint32_t hi() const { return static_cast<std::uint32_t>(key); }
};

/// The edges of every face that names three distinct vertices, by key, then face.
std::vector<FaceEdge> sorted_face_edges(const SoupView& soup);

}  // namespace meshprep
