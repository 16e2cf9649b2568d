#pragma once
// The topological moves of tet improvement (Shewchuk, "Two discrete optimization algorithms for
// the topological improvement of tetrahedral meshes", 2002; Klingner & Shewchuk, IMR 2007):
// - edge removal: the n tets around an interior edge ab are replaced by the 2(n - 2) tets that
//   join a and b to a triangulation of the ring of their other corners, the triangulation that
//   maximises the worst quality, found by dynamic programming over the ring polygon (Klincsek's
//   algorithm). n = 3 is the 3-2 flip, n = 4 the 4-4 flip.
// - multi-face removal, its inverse: the faces sandwiched between two vertices a and b (each of
//   them a face of a tet with apex a and of one with apex b) are removed and the tets around them
//   replaced by tets around the new edge ab; the set of faces removed is the one that maximises
//   the worst new tet, again by dynamic programming over the tree of candidate faces. One face is
//   the 2-3 flip.
// A move is a candidate: the tets it removes, the tets it makes and the worst of each; the best
// candidate is returned whether or not it improves (a compound move may still use it).

#include "tet_complex.h"

#include <vector>

namespace meshprep::improve {

struct Move {
  std::vector<TetId> old;
  std::vector<Tetrahedron> fresh;
  double old_worst = 0;  ///< the smallest quality among `old`
  double new_worst = 0;  ///< the smallest quality among `fresh`
  bool improves() const { return !fresh.empty() && new_worst > old_worst; }
};

/// The best removal of the edge (a, b) of tet t (rings of at most `max_ring` tets).
/// Empty (no fresh tets) when the edge is constrained or its ring too large.
Move edge_removal(const TetComplex& mesh, TetId t, VertexId a, VertexId b, std::size_t max_ring);

/// The best multi-face removal that starts with the face of tet t opposite `corner`.
/// Empty when that face is constrained.
Move multi_face_removal(const TetComplex& mesh, TetId t, int corner, std::size_t max_faces);

}  // namespace meshprep::improve
