#pragma once
// The faces of a tet mesh grouped by their corners: which tets share each face. Shared by the
// readers (import.cpp), which check and complete the boundary, and tet_boundary.

#include "meshprep/fem/tet_mesh.h"

#include <cstdint>
#include <vector>

namespace meshprep::detail {

/// Face k of `tet`, the one opposite its corner k, oriented away from corner k when the tet is
/// positively oriented.
Triangle face_of(const Tetrahedron& tet, int k);

/// The corners in ascending order (the key of a face whatever its orientation).
Triangle sorted(Triangle corners);

/// Whether triangle a lists the corners of b in the same cyclic order.
bool same_orientation(const Triangle& a, const Triangle& b);

/// No tet has the face (tet_faces_of).
inline constexpr std::uint32_t kNoTetFace = ~std::uint32_t{0};

/// For each of `faces`, a tet face with its corners, as 4 * tet + k (face_of(tet, k)): the one of
/// the same orientation (the face is outward of that tet) where there is one, else the first;
/// kNoTetFace if no tet has it. Only tet faces whose three corners are all corners of `faces` are
/// looked up, by binary search (most of a mesh's have one inside): for the boundary faces of a
/// mesh this is a pass over the tets, not a sort of all their faces (TetFaces).
/// \pre fewer than 2^30 tets.
std::vector<std::uint32_t> tet_faces_of(const std::vector<Tetrahedron>& tets, const std::vector<Triangle>& faces);

/// Every face of every tet, sorted by its corners: the entries of one face are adjacent, one per
/// tet that has it, in tet order. 4 faces per tet are numbered in 32 bits.
/// \pre fewer than 2^30 tets.
class TetFaces {
 public:
  struct Entry {
    Triangle key;            ///< sorted corners
    std::uint32_t tet_face;  ///< 4 * tet + k (face_of(tet, k))
  };

  explicit TetFaces(const std::vector<Tetrahedron>& tets);

  const std::vector<Entry>& entries() const { return entries_; }

  /// The number of entries with the key of entry `first`, from `first` on (the tets of that face
  /// when `first` is the face's first entry).
  std::size_t group_size(std::size_t first) const;

  /// The first entry of the face with these sorted corners, or entries().size() if no tet has it.
  std::size_t find(const Triangle& key) const;

  /// The faces that belong to one tet only, as 4 * tet + k, in tet order; with `excluded` (one
  /// flag per entry), those whose entry is flagged are left out.
  std::vector<std::uint32_t> single_tet_faces(const std::vector<bool>* excluded = nullptr) const;

 private:
  std::vector<Entry> entries_;
};

}  // namespace meshprep::detail
