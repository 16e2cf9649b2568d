#pragma once
// The neighbourhoods of RBF smoothing (smooth.h): a vertex's neighbours within a few rings on its
// side of any crease.

#include "meshprep/core/mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// How far a neighbourhood reaches, in edges.
constexpr int kSmoothingRings = 4;

/// Where the neighbourhood of a vertex may reach: not across a crease, not to a face turned more
/// than the feature angle from the side it starts on (a crease that fades out, or the far side of
/// a corner, would otherwise be reached around the end of the crease line).
struct FeatureMap {
  const std::vector<Vec3>& normals;  // unit face normals
  std::vector<char> crease;          // per edge
  double cos_limit = -1;
};

/// The mesh's vertex graph in compressed rows, with the crease flag of each edge and the filtered
/// normal of each vertex (the mean of its faces'): nearby_vertices walks it, 2.4x faster than
/// same_side_neighbours' face search with OpenMesh's circulators.
struct VertexGraph {
  std::vector<std::uint32_t> first;  // row v is [first[v], first[v + 1])
  std::vector<std::uint32_t> neighbour;
  std::vector<char> crease;          // per entry of `neighbour`
  std::vector<Vec3> normal;          // per vertex
};

/// The graph of `mesh` with the crease flags of `features`.
VertexGraph vertex_graph(const TriMesh& mesh, const FeatureMap& features);

/// The vertices within kSmoothingRings edges of v, reached without walking along a crease (unless
/// `across_creases`) and whose normals are within the feature angle of v's (cos_limit; -1 for
/// any): v's neighbourhood on its side of any feature. The `count` nearest to v (v excluded), in
/// no particular order.
std::vector<Vec3> nearby_vertices(const TriMesh& mesh, const VertexGraph& graph, std::uint32_t v, double cos_limit,
                                  bool across_creases, std::size_t count);

/// The vertices of the faces reached from `seeds` across non-crease edges, among the faces whose
/// corners are all within kSmoothingRings rings of v and whose normals are within the feature
/// angle of the seeds' mean normal: v's neighbourhood on one side of a feature it lies on. The
/// `count` nearest to v (v excluded), in no particular order.
std::vector<Vec3> same_side_neighbours(const TriMesh& mesh, TriMesh::VertexHandle v,
                                       const std::vector<TriMesh::FaceHandle>& seeds, const FeatureMap& features,
                                       std::size_t count);

/// v's faces split at the creases into fans (v must be on a crease).
std::vector<std::vector<TriMesh::FaceHandle>> fans_between_creases(const TriMesh& mesh, TriMesh::VertexHandle v,
                                                                   const std::vector<char>& crease);

}  // namespace meshprep::detail
