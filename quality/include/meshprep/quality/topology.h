#pragma once
/// \file topology.h
/// Combinatorial checks on an indexed triangle soup, computed on the faces exactly as written
/// (a halfedge structure cannot hold the non-manifold cases we must report).

#include "meshprep/core/mesh.h"
#include "meshprep/core/soup_view.h"

#include <optional>
#include <vector>

namespace meshprep {

struct Topology {
  std::size_t referenced_vertices = 0;  ///< vertices used by at least one face
  std::size_t isolated_vertices = 0;    ///< points no face uses
  std::size_t edges = 0;                ///< distinct undirected edges of the non-degenerate faces
  std::size_t border_edges = 0;         ///< edges with one incident face
  std::size_t non_manifold_edges = 0;   ///< edges with three or more incident faces
  std::size_t non_manifold_vertices = 0;  ///< vertices whose incident faces form more than one fan
  std::size_t inconsistent_edges = 0;   ///< two-face edges traversed in the same direction by both
  std::size_t boundary_loops = 0;       ///< connected chains of border edges
  std::size_t components = 0;           ///< edge-connected components of faces
  std::size_t repeated_index_faces = 0;  ///< faces naming a vertex twice (combinatorially degenerate)
  std::size_t duplicate_faces = 0;      ///< faces on the same vertex set as an earlier face
  bool closed = false;                  ///< no border edge
  bool manifold = false;                ///< edge- and vertex-manifold, no repeated-index face
  bool oriented = false;                ///< manifold and every interior edge used once in each direction
  long long euler_characteristic = 0;   ///< V - E + F over referenced vertices and non-degenerate faces
  std::optional<long long> genus;       ///< sum of genera, (2C - chi)/2, for closed manifold meshes
  // The first offending faces of each kind (at most 100 each), for diagnoses:
  std::vector<std::size_t> border_edge_faces;        ///< faces with a border edge
  std::vector<std::size_t> non_manifold_edge_faces;  ///< faces on a non-manifold edge
  std::vector<std::size_t> non_manifold_vertex_faces;  ///< faces around a non-manifold vertex
  std::vector<std::size_t> inconsistent_edge_faces;  ///< faces across an inconsistently oriented edge
  std::vector<std::size_t> repeated_index_face_indices;  ///< faces naming a vertex twice
  std::vector<std::size_t> duplicate_face_indices;   ///< the later copy of each duplicate
};

/// Analyse the connectivity of `soup`.
Topology analyze_topology(const SoupView& soup);

}  // namespace meshprep
